// Parsing a request's head: http_request.h.
#include "net/http_request.h"

#include <algorithm>

namespace vkrt {
namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

HeadParse refused(int status, const char* reason) {
  HeadParse p;
  p.kind = HeadParse::Refused;
  p.status = status;
  p.reason = reason;
  return p;
}

// "a=1&b=2" into `query` (a later repeat of a name wins); false for a bad escape.
bool parseQuery(std::string_view text, std::map<std::string, std::string>& query) {
  while (!text.empty()) {
    const std::size_t amp = std::min(text.find('&'), text.size());
    const std::string_view pair = text.substr(0, amp);
    text.remove_prefix(std::min(amp + 1, text.size()));
    if (pair.empty()) continue;
    const std::size_t eq = std::min(pair.find('='), pair.size());
    std::string name, value;
    if (!percentDecode(pair.substr(0, eq), true, name)) return false;
    if (eq < pair.size() && !percentDecode(pair.substr(eq + 1), true, value)) return false;
    query[name] = value;
  }
  return true;
}

}  // namespace

bool percentDecode(std::string_view text, bool plusIsSpace, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '%') {
      if (i + 2 >= text.size()) return false;
      const int hi = hexValue(text[i + 1]), lo = hexValue(text[i + 2]);
      if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) return false;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    } else if (c == '+' && plusIsSpace) {
      c = ' ';
    }
    out += c;
  }
  return true;
}

HeadParse parseRequestHead(std::string_view received) {
  const std::size_t lineEnd = received.find('\n');
  if ((lineEnd == std::string_view::npos ? received.size() : lineEnd) > kMaxRequestLine)
    return refused(414, "request line too long");
  std::size_t end = received.find("\r\n\r\n");
  std::size_t endLength = 4;
  if (const std::size_t bare = received.find("\n\n"); bare < end) end = bare, endLength = 2;
  if (end == std::string_view::npos)
    return received.size() > kMaxRequestHead ? refused(431, "request header fields too large") : HeadParse{};
  if (end + endLength > kMaxRequestHead) return refused(431, "request header fields too large");

  std::string_view line = received.substr(0, lineEnd);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::size_t sp1 = line.find(' '), sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp1 == 0 || sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos)
    return refused(400, "malformed request line");
  const std::string_view method = line.substr(0, sp1), target = line.substr(sp1 + 1, sp2 - sp1 - 1),
                         version = line.substr(sp2 + 1);
  if (version != "HTTP/1.1" && version != "HTTP/1.0") return refused(505, "HTTP version not supported");
  for (char c : method)
    if (c < 'A' || c > 'Z') return refused(400, "malformed method");
  if (target.empty() || target.front() != '/') return refused(400, "the target must be a path");
  for (char c : target)
    if (static_cast<unsigned char>(c) <= 0x20 || static_cast<unsigned char>(c) >= 0x7f)
      return refused(400, "malformed target");

  HeadParse p;
  p.kind = HeadParse::Complete;
  p.request.method = std::string(method);
  const std::size_t question = std::min(target.find('?'), target.size());
  if (!percentDecode(target.substr(0, question), false, p.request.path) ||
      (question < target.size() && !parseQuery(target.substr(question + 1), p.request.query)))
    return refused(400, "malformed escape in the target");
  return p;
}

}  // namespace vkrt
