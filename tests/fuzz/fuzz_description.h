#pragma once
// The valve description's two text forms: the default parameter file as lines, the JSON form's value strings.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace fuzz
{
  // ---- the default parameter file, as lines ---------------------------------------------------------
  struct PrmLine
  {
    enum Kind
    {
      other,
      subsection,
      end,
      entry
    } kind = other;
    std::string text;
    std::string indent, name, value; ///< subsection name, or entry key and value
    std::string path;                ///< "Subsection/Key" of an entry
  };

  struct Prm
  {
    std::vector<PrmLine> lines;
    std::vector<std::size_t> entries, subsections; ///< indices into lines

    std::string text() const
    {
      std::string s;
      for (const auto &l : lines)
        s += l.text + "\n";
      return s;
    }
    bool has(const std::string &path) const
    {
      for (auto k : entries)
        if (lines[k].path == path)
          return true;
      return false;
    }
  };

  Prm parse_prm(const std::string &text);

  void set_value(PrmLine &l, const std::string &value);

  // ---- JSON --------------------------------------------------------------------------------------------
  /// A string value of the JSON form: where its characters are and which entry it belongs to.
  struct JsonValue
  {
    std::size_t begin, end; ///< [begin, end) is the string including its quotes
    std::string path;
  };

  /// The `key' strings ("value", "pattern_description") of `servodrift params --format json', found
  /// by a minimal scanner (keys, strings, object nesting): enough for the text deal.II writes, no
  /// general parser.
  std::vector<JsonValue> json_values(const std::string &json, const std::string &key = "value");

  /// The declared range of a numeric entry (or of a list's elements), from its pattern description
  /// "[Double lo...hi (inclusive)]", "[Integer range lo...hi ...]" or "[List of <[Double ...]> ...]".
  struct Range
  {
    bool integer = false, list = false;
    double lo = 0, hi = 0;
  };

  /// Every numeric entry's range by path: the surfaces' mutations put values at and beyond its ends.
  std::map<std::string, Range> numeric_ranges(const std::string &json);

  std::string json_string(const std::string &s);
} // namespace fuzz
