// A small HTTP/1.1 server for `vkrt view` (cli/web_view.h): one thread of its own, one poll()
// loop over non-blocking sockets, so that nothing a browser does (or fails to do) ever waits
// on the render, nor the render on it. Each response closes its connection, except an event
// stream (text/event-stream), which stays open and is sent the site's events as they come;
// a stream whose earlier event has not drained yet is sent the latest one when it has (a slow
// browser sees fewer events, never a growing queue).
//
// Bounded: at most kMaxConnections at once; when all are taken, a new one takes the place of
// the oldest that has not sent its request yet (which gets 503), else it gets 503 itself, so
// that idle connections cannot keep the page from its browser. A request line or head past
// http_request.h's limits is refused (414, 431); a head not received within kHeadSeconds, or
// output that does not move for kStallSeconds, closes the connection. Only GET is answered
// (405 otherwise). The thread runs at a lower priority than the render (nice +10): encoding
// the page's image yields the CPU to it.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "net/http_request.h"
#include "platform/socket.h"

namespace vkrt {

inline constexpr int kMaxConnections = 32;
inline constexpr int kHeadSeconds = 10;
inline constexpr int kStallSeconds = 20;
inline constexpr int kKeepAliveSeconds = 15;   // an idle stream is sent a comment this often

struct HttpResponse {
  int status = 200;
  std::string contentType = "text/plain; charset=utf-8";
  std::string body;
  // The body when it is large and the same for many (the image): shared, not copied per
  // connection. Replaces `body` when set.
  std::shared_ptr<const std::string> sharedBody;
  bool stream = false;          // an event stream: body is its first event
  std::string extraHeaders;     // whole lines, each ending in "\r\n"
};

// What the server serves. Both are called on the server's thread, never two at once.
class HttpSite {
 public:
  virtual ~HttpSite() = default;
  virtual HttpResponse respond(const HttpRequest& request) = 0;
  // For an event stream that has seen the site's state up to `seen`: the event to send (and
  // `seen` moved on), or "" when there is nothing newer.
  virtual std::string nextEvent(std::uint64_t& seen) = 0;
};

class HttpServer {
 public:
  // Listens on `host` (a name or a numeric address; "" = 127.0.0.1) and `port` (0: a free
  // one). Throws IoError when it cannot (the address is not this machine's, the port is taken).
  HttpServer(const std::string& host, int port, HttpSite& site);
  ~HttpServer();   // stops the thread and closes every connection
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  int port() const { return port_; }
  // The address it listens on, as a URL's host: "127.0.0.1", "[::1]".
  const std::string& urlHost() const { return urlHost_; }
  // The site has something new for its streams: wakes the loop. Any thread; never blocks.
  void notify();

 private:
  void run();

  HttpSite& site_;
  platform::Socket listen_;
  std::unique_ptr<platform::PollWaker> wake_;
  int port_ = 0;
  std::string urlHost_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace vkrt
