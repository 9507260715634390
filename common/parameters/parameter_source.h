#pragma once
// Where the values of a valve description come from when its structs parse them: deal.II's
// ParameterHandler (the program: declarations, ranges, documentation; parameter_input.h) or a
// parameter file as deal.II printed it, read without deal.II (the FMU's resources/parameters.prm,
// whose entries deal.II checked when it wrote them). The structs' parse_parameters read through
// this interface only, so that the valve's core links no deal.II.
#include <map>
#include <string>
#include <vector>

namespace servodrift
{
  namespace parameters
  {
    /// `text' without leading and trailing whitespace
    std::string trimmed(const std::string &text);
    /// The items of a list separated by `separator', each trimmed; a trailing separator ends the
    /// list; with ' ' as separator, the words (deal.II's Utilities::split_string_list).
    std::vector<std::string> split_list(const std::string &text, char separator = ',');
  } // namespace parameters

  class ParameterSource
  {
  public:
    virtual ~ParameterSource() = default;
    virtual void enter_subsection(const std::string &name) = 0;
    virtual void leave_subsection() = 0;
    /// The text of entry `key' of the current subsection. Throws InputError naming it if absent.
    virtual std::string get(const std::string &key) const = 0;
    /// The entry as a finite number, an integer, true/false (yes/no), a comma-separated list.
    /// Throws InputError naming the entry and the text when it is not one.
    virtual double get_double(const std::string &key) const;
    virtual long get_integer(const std::string &key) const;
    virtual bool get_bool(const std::string &key) const;
    std::vector<double> get_double_list(const std::string &key) const;
    std::vector<int> get_integer_list(const std::string &key) const;

  protected:
    /// "Subsection/Key" of `key' in the current subsection, for messages
    virtual std::string path_of(const std::string &key) const = 0;
    /// "file: " where the values come from a file, for messages
    virtual std::string origin() const { return ""; }
  };

  /// A parameter file in deal.II's PRM format (`subsection', `set Key = value', `end', `#'
  /// comments, a trailing `\' continuing a line), read into memory.
  class PrmText : public ParameterSource
  {
  public:
    /// `name' is the file's name in messages. Throws InputError (unbalanced `end', a line that is
    /// none of the above).
    PrmText(const std::string &text, const std::string &name);
    void enter_subsection(const std::string &name) override;
    void leave_subsection() override;
    std::string get(const std::string &key) const override;

  protected:
    std::string path_of(const std::string &key) const override;
    std::string origin() const override { return name + ": "; }

  private:
    std::string name;
    std::map<std::string, std::string> values; ///< "Subsection/.../Key" -> value
    std::vector<std::string> current;          ///< the subsections entered
  };
} // namespace servodrift
