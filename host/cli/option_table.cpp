// The table-independent part of option parsing (host/cli/option_table.h).
#include "cli/option_table.h"

#include <algorithm>

#include "util/errors.h"             // UsageError
#include "util/text.h"   // echoed
#include "util/suggest.h"

namespace vkrt {

namespace {

// Each spelling of "-o, --output", in turn.
template <class Visit>
void forEachSpelling(std::string_view names, Visit visit) {
  while (!names.empty()) {
    const std::size_t comma = std::min(names.find(','), names.size());
    visit(names.substr(0, comma));
    names.remove_prefix(std::min(comma + 1, names.size()));
    while (!names.empty() && names.front() == ' ') names.remove_prefix(1);
  }
}

}  // namespace

bool spelledAs(std::string_view names, std::string_view given) {
  bool found = false;
  forEachSpelling(names, [&](std::string_view spelling) { found = found || spelling == given; });
  return found;
}

void appendLongNames(std::string_view names, std::vector<std::string_view>& out) {
  forEachSpelling(names, [&](std::string_view spelling) {
    if (spelling.substr(0, 2) == "--") out.push_back(spelling.substr(2));
  });
}

std::string unknownOption(const std::string& what, const std::string& option, const std::string& note,
                          std::span<const std::string_view> known) {
  std::string_view name = option;
  name = name.substr(0, name.find('='));
  name.remove_prefix(std::min(name.find_first_not_of('-'), name.size()));
  return "unknown " + what + " '" + echoed(option) + "'" + (note.empty() ? "" : " " + note) +
         didYouMean(name, known, "--");
}

Argument classify(const std::string& a, bool endOfOptions) {
  if (endOfOptions || a.empty() || a[0] != '-' || a == "-") return {Argument::Operand, a, "", false};
  if (a == "--") return {Argument::EndOfOptions, a, "", false};
  // --name=value is accepted as well as --name value.
  if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos)
    return {Argument::Option, a.substr(0, eq), a.substr(eq + 1), true};
  return {Argument::Option, a, "", false};
}

std::string takeValue(const Argument& arg, const std::vector<std::string>& args, std::size_t& i) {
  if (arg.hasInline) return arg.inlineValue;
  if (i + 1 >= args.size()) throw UsageError("option " + echoed(arg.name) + " needs a value");
  return args[++i];
}

}  // namespace vkrt
