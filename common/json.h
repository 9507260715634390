#pragma once
// A minimal JSON value for writing fits.json and other machine-readable summaries.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace servodrift
{
  class Json
  {
  public:
    Json() = default; // null
    Json(double number);
    Json(int number);
    Json(unsigned int number);
    Json(std::size_t number);
    Json(bool boolean);
    Json(const char *text);
    Json(std::string text);
    Json(const std::vector<double> &numbers);
    Json(const std::vector<std::string> &texts);

    static Json array();
    static Json object();
    /// Appends to an array.
    Json &push_back(Json value);
    /// Sets a key of an object (keys keep their insertion order).
    Json &set(const std::string &key, Json value);

    /// Pretty-printed with two-space indents; numbers with 15 significant digits; a non-finite
    /// number is written as null.
    std::string dump() const;

  private:
    enum class Kind { null, number, boolean, text, array, object } kind = Kind::null;
    double number = 0;
    bool boolean = false;
    std::string text;
    std::vector<Json> items;
    std::vector<std::pair<std::string, Json>> members;
    void dump_to(std::string &out, int indent) const;
  };
} // namespace servodrift
