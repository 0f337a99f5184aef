// The head of an HTTP/1.x request as `vkrt view`'s server reads it (net/http_server.h): the
// request line and header fields, parsed with limits on their size, and the target split into
// its path and query parameters (percent-decoded). Nothing here reads a socket.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>

namespace vkrt {

// Past these, a request is refused (414: its request line; 431: the whole head).
inline constexpr std::size_t kMaxRequestLine = 2048;
inline constexpr std::size_t kMaxRequestHead = 8192;

struct HttpRequest {
  std::string method;                         // "GET"
  std::string path;                           // "/image.png", decoded
  std::map<std::string, std::string> query;   // "?t=abc&v=3": {t: abc, v: 3}, decoded
};

// What the bytes received so far on a connection hold.
struct HeadParse {
  enum Kind { Incomplete, Complete, Refused } kind = Incomplete;
  int status = 0;         // Refused: 400 (malformed), 414, 431 (too large), 505 (not HTTP/1.x)
  std::string reason;     // Refused: in a few words, for the response's body
  HttpRequest request;    // Complete
};
HeadParse parseRequestHead(std::string_view received);

// "%41+b" -> "A b" ('+' as a space only in a query); false for a '%' not followed by two hex
// digits, or one that decodes to NUL.
bool percentDecode(std::string_view text, bool plusIsSpace, std::string& out);

}  // namespace vkrt
