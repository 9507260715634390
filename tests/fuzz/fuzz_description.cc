// The parameter file parsed into lines and entries; the JSON form's value strings found and written.
#include "fuzz_description.h"

#include "fuzz_support.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace fuzz
{
  Prm parse_prm(const std::string &text)
  {
    Prm prm;
    std::vector<std::string> stack;
    std::istringstream in(text);
    for (std::string raw; std::getline(in, raw);)
      {
        PrmLine l;
        l.text = raw;
        l.indent = raw.substr(0, raw.find_first_not_of(' ') == std::string::npos ? 0 : raw.find_first_not_of(' '));
        const std::string t = trim(raw);
        if (t.rfind("subsection ", 0) == 0)
          {
            l.kind = PrmLine::subsection;
            l.name = trim(t.substr(11));
            stack.push_back(l.name);
            prm.subsections.push_back(prm.lines.size());
          }
        else if (t == "end")
          {
            l.kind = PrmLine::end;
            if (!stack.empty())
              stack.pop_back();
          }
        else if (t.rfind("set ", 0) == 0 && t.find('=') != std::string::npos)
          {
            l.kind = PrmLine::entry;
            l.name = trim(t.substr(4, t.find('=') - 4));
            l.value = trim(t.substr(t.find('=') + 1));
            for (const auto &s : stack)
              l.path += s + "/";
            l.path += l.name;
            prm.entries.push_back(prm.lines.size());
          }
        prm.lines.push_back(l);
      }
    return prm;
  }

  void set_value(PrmLine &l, const std::string &value)
  {
    l.value = value;
    l.text = l.indent + "set " + l.name + " = " + value;
  }

  std::vector<JsonValue> json_values(const std::string &json, const std::string &key)
  {
    std::vector<JsonValue> found;
    std::vector<std::string> stack;
    std::string last_key;
    for (std::size_t k = 0; k < json.size(); ++k)
      {
        const char c = json[k];
        if (c == '{')
          stack.push_back(last_key);
        else if (c == '}' && !stack.empty())
          stack.pop_back();
        else if (c == '"')
          {
            std::size_t e = k + 1;
            std::string s;
            for (; e < json.size() && json[e] != '"'; ++e)
              {
                if (json[e] == '\\')
                  ++e;
                s += json[e];
              }
            const std::size_t after = json.find_first_not_of(" \t\r\n", e + 1);
            const bool is_key = after != std::string::npos && json[after] == ':';
            if (is_key)
              last_key = s;
            else if (last_key == key)
              {
                std::string path;
                for (std::size_t d = 1; d < stack.size(); ++d)
                  path += (path.empty() ? "" : "/") + stack[d];
                found.push_back({k, e + 1, path});
              }
            k = e;
          }
      }
    return found;
  }

  std::map<std::string, Range> numeric_ranges(const std::string &json)
  {
    std::map<std::string, Range> ranges;
    for (const JsonValue &v : json_values(json, "pattern_description"))
      {
        std::string d = json.substr(v.begin + 1, v.end - v.begin - 2);
        Range r;
        if (d.rfind("[List of <", 0) == 0)
          r.list = true, d = d.substr(10);
        if (d.rfind("[Integer range ", 0) == 0)
          r.integer = true, d = d.substr(15);
        else if (d.rfind("[Double ", 0) == 0)
          d = d.substr(8);
        else
          continue;
        const std::size_t dots = d.find("...");
        if (dots == std::string::npos)
          continue;
        char *end = nullptr;
        r.lo = std::strtod(d.c_str(), &end);
        if (end != d.c_str() + dots)
          continue;
        r.hi = std::strtod(d.c_str() + dots + 3, &end);
        if (end == d.c_str() + dots + 3)
          continue;
        ranges[v.path] = r;
      }
    return ranges;
  }

  std::string json_string(const std::string &s)
  {
    std::string out = "\"";
    for (char c : s)
      {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\')
          out += std::string("\\") + c;
        else if (u < 0x20)
          {
            char hex[8];
            std::snprintf(hex, sizeof(hex), "\\u%04x", u);
            out += hex;
          }
        else
          out += c; // bytes >= 0x80 raw: invalid UTF-8 stays invalid
      }
    return out + "\"";
  }
} // namespace fuzz
