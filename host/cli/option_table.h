// A command's options as one table: each row an option's spellings, its argument, its line of
// `vkrt --help` and its setter. Parsing, --help, the names for "did you mean" and the test
// that holds doc/vkrt.1 to --help all read the rows (cli/options.cpp holds the tables). No
// rendering here, and nothing about any one command.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkrt {

// An option's value, taken only when its setter asks (so a setter may refuse the option
// before it looks for a value): `--name=value`, or the next argument. Throws UsageError
// ("option --spp needs a value").
struct OptionValue {
  std::string name;                        // the option as given, without "=value": "-o", "--output"
  std::function<std::string()> take;
  std::string operator()() const { return take(); }
};

// Where a row is in `vkrt --help`.
enum class HelpSection {
  Options,      // "options:"
  Comparison,   // "comparison options (diff, --check and --compare):"
  Grade,        // under grade's paragraph
  View,         // under view's paragraph (rows of the render command's table)
  Last,         // -q, -h, --version, after every command's
  Elsewhere,    // not in this command's part: its help is under another command's rows, or in a paragraph
  Hidden,       // for the benchmark and the tests: not in --help, the man page or the suggestions
};

template <class Options>
struct OptionRow {
  std::string_view names;      // its spellings, as --help writes them: "-o, --output"
  std::string_view argument;   // its value, as --help writes it ("FILE", "REF{ext}"); "" for a flag
  // Its text in --help (placeholders: usage_text.h), lines separated by '\n'; a line that
  // starts with '\f' is filled to the width of --help.
  std::string_view help;
  void (*set)(Options&, const OptionValue&);   // nullptr: one more --help entry of the option above
  HelpSection section = HelpSection::Options;
  std::string_view shownAs = "";   // --help's left column, when not "names argument"
};

// "--output" of "-o, --output": whether `given` is one of `names`.
bool spelledAs(std::string_view names, std::string_view given);

// The long names of `names` ("output" of "-o, --output"), appended to `out`.
void appendLongNames(std::string_view names, std::vector<std::string_view>& out);

// "unknown option '--bakcend'; did you mean '--backend'?": the option without its dashes (and
// without =VALUE) against `known`.
std::string unknownOption(const std::string& what, const std::string& option, const std::string& note,
                          std::span<const std::string_view> known);

// One argument of a command line, told apart: an operand, "--", or an option with its name and
// the value after '=' (only for "--name=value").
struct Argument {
  enum Kind { Operand, EndOfOptions, Option } kind;
  std::string name, inlineValue;
  bool hasInline = false;
};
Argument classify(const std::string& a, bool endOfOptions);

// The value of the option at args[i]: its inline value, or args[++i]. Throws UsageError.
std::string takeValue(const Argument& arg, const std::vector<std::string>& args, std::size_t& i);

// The long names of the rows that --help or a paragraph lists, in the rows' order: what a
// misspelled option is suggested from.
template <class Options>
std::vector<std::string_view> suggestedNames(std::span<const OptionRow<Options>> rows) {
  std::vector<std::string_view> names;
  for (const OptionRow<Options>& row : rows)
    if (row.set && row.section != HelpSection::Hidden) appendLongNames(row.names, names);
  return names;
}

// Parses args[first...] against `rows` into `o`: each operand to `operand`; an option no row
// spells (or a flag given "=value") to `unknown`, which throws.
template <class Options>
void parseArguments(const std::vector<std::string>& args, std::size_t first, std::span<const OptionRow<Options>> rows,
                    Options& o, const std::function<void(const std::string&)>& operand,
                    const std::function<void(const std::string&)>& unknown) {
  bool endOfOptions = false;
  for (std::size_t i = first; i < args.size(); ++i) {
    const Argument arg = classify(args[i], endOfOptions);
    if (arg.kind == Argument::Operand) {
      operand(args[i]);
      continue;
    }
    if (arg.kind == Argument::EndOfOptions) {
      endOfOptions = true;
      continue;
    }
    const OptionRow<Options>* row = nullptr;
    for (const OptionRow<Options>& r : rows)
      if (r.set && spelledAs(r.names, arg.name)) {
        row = &r;
        break;
      }
    if (!row || (row->argument.empty() && arg.hasInline)) {
      unknown(args[i]);
      continue;
    }
    row->set(o, OptionValue{arg.name, [&] { return takeValue(arg, args, i); }});
  }
}

}  // namespace vkrt
