#include "common/json.h"

#include <cmath>
#include <cstdio>

namespace servodrift
{
  Json::Json(double n) : kind(Kind::number), number(n) {}
  Json::Json(int n) : kind(Kind::number), number(n) {}
  Json::Json(unsigned int n) : kind(Kind::number), number(n) {}
  Json::Json(std::size_t n) : kind(Kind::number), number(static_cast<double>(n)) {}
  Json::Json(bool b) : kind(Kind::boolean), boolean(b) {}
  Json::Json(const char *t) : kind(Kind::text), text(t) {}
  Json::Json(std::string t) : kind(Kind::text), text(std::move(t)) {}
  Json::Json(const std::vector<double> &numbers) : kind(Kind::array)
  {
    for (double n : numbers)
      items.emplace_back(n);
  }
  Json::Json(const std::vector<std::string> &texts) : kind(Kind::array)
  {
    for (const auto &t : texts)
      items.emplace_back(t);
  }

  Json Json::array()
  {
    Json j;
    j.kind = Kind::array;
    return j;
  }

  Json Json::object()
  {
    Json j;
    j.kind = Kind::object;
    return j;
  }

  Json &Json::push_back(Json value)
  {
    items.push_back(std::move(value));
    return *this;
  }

  Json &Json::set(const std::string &key, Json value)
  {
    for (auto &m : members)
      if (m.first == key)
        {
          m.second = std::move(value);
          return *this;
        }
    members.emplace_back(key, std::move(value));
    return *this;
  }

  std::string Json::dump() const
  {
    std::string out;
    dump_to(out, 0);
    out += "\n";
    return out;
  }

  namespace
  {
    void quote(std::string &out, const std::string &s)
    {
      out += '"';
      for (char c : s)
        switch (c)
          {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char buffer[8];
                  std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
                  out += buffer;
                }
              else
                out += c;
          }
      out += '"';
    }
  } // namespace

  void Json::dump_to(std::string &out, int indent) const
  {
    const std::string pad(2 * (indent + 1), ' '), pad_end(2 * indent, ' ');
    switch (kind)
      {
        case Kind::null: out += "null"; break;
        case Kind::boolean: out += boolean ? "true" : "false"; break;
        case Kind::text: quote(out, text); break;
        case Kind::number:
          if (!std::isfinite(number))
            out += "null";
          else
            {
              char buffer[40];
              std::snprintf(buffer, sizeof(buffer), "%.15g", number);
              out += buffer;
            }
          break;
        case Kind::array:
          {
            bool simple = true;
            for (const auto &i : items)
              simple = simple && (i.kind == Kind::number || i.kind == Kind::text || i.kind == Kind::null);
            out += "[";
            for (std::size_t k = 0; k < items.size(); ++k)
              {
                out += k ? (simple ? ", " : ",\n" + pad) : (simple ? "" : "\n" + pad);
                items[k].dump_to(out, indent + 1);
              }
            out += simple || items.empty() ? "]" : "\n" + pad_end + "]";
            break;
          }
        case Kind::object:
          out += "{";
          for (std::size_t k = 0; k < members.size(); ++k)
            {
              out += (k ? ",\n" : "\n") + pad;
              quote(out, members[k].first);
              out += ": ";
              members[k].second.dump_to(out, indent + 1);
            }
          out += members.empty() ? "}" : "\n" + pad_end + "}";
          break;
      }
  }
} // namespace servodrift
