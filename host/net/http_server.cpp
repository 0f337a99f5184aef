// The server's loop: http_server.h.
#include "net/http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <memory>
#include <vector>

#include "util/errors.h"

namespace vkrt {
namespace {

using Clock = std::chrono::steady_clock;

const char* statusText(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 414: return "URI Too Long";
    case 431: return "Request Header Fields Too Large";
    case 503: return "Service Unavailable";
    case 505: return "HTTP Version Not Supported";
    default: return "Error";
  }
}

// The response's head and body, as sent. Every response keeps what it serves out of caches
// and its address (which holds the token) out of Referer headers.
std::string responseBytes(const HttpResponse& r) {
  std::string head = "HTTP/1.1 " + std::to_string(r.status) + " " + statusText(r.status) + "\r\n" +
                     "Content-Type: " + r.contentType + "\r\n" +
                     "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\n" +
                     r.extraHeaders;
  if (r.stream) return head + "Connection: keep-alive\r\n\r\n" + r.body;
  if (r.sharedBody)   // (sent from where it is: Connection::body)
    return head + "Content-Length: " + std::to_string(r.sharedBody->size()) + "\r\nConnection: close\r\n\r\n";
  return head + "Content-Length: " + std::to_string(r.body.size()) + "\r\nConnection: close\r\n\r\n" + r.body;
}

HttpResponse errorResponse(int status, const std::string& reason) {
  HttpResponse r;
  r.status = status;
  r.body = std::to_string(status) + " " + statusText(status) + (reason.empty() ? "" : ": " + reason) + "\n";
  return r;
}

void setNonBlocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

struct Connection {
  int fd = -1;
  // Draining: the response sent and the socket shut for writing; what the browser still
  // sends is read and dropped until it closes (closing at once could reset the connection
  // before the browser has read a refusal).
  enum State { Reading, Writing, Streaming, Draining } state = Reading;
  std::string in, out;
  std::size_t sent = 0;            // of `out`
  std::shared_ptr<const std::string> body;   // a shared body, sent after `out`
  std::size_t bodySent = 0;
  std::uint64_t seen = 0;          // Streaming: the site's state it has been sent
  Clock::time_point opened, moved;   // accepted; output last moved (or a stream's last event)
  bool closing = false;
  bool eof = false;   // the browser has closed its side: nothing more to read
  ~Connection() {
    if (fd >= 0) ::close(fd);
  }
  bool pending() const { return sent < out.size() || (body && bodySent < body->size()); }
  void queue(std::string bytes) {
    if (!pending()) out.clear(), sent = 0, body.reset(), bodySent = 0;
    out += bytes;
  }
};

// Sends what `c` has pending, as far as the socket takes it; false when the peer is gone.
bool flush(Connection& c) {
  while (c.pending()) {
    const bool head = c.sent < c.out.size();
    const char* from = head ? c.out.data() + c.sent : c.body->data() + c.bodySent;
    const std::size_t left = head ? c.out.size() - c.sent : c.body->size() - c.bodySent;
    const ssize_t n = ::send(c.fd, from, left, MSG_NOSIGNAL);
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    (head ? c.sent : c.bodySent) += static_cast<std::size_t>(n);
    c.moved = Clock::now();
  }
  return true;
}

// What the browser sent: the request's head, answered once whole (or refused); after it, a
// stream's or a finished request's further bytes are read and dropped.
void receiveFrom(Connection& c, HttpSite& site, Clock::time_point now) {
  char buffer[4096];
  const ssize_t n = ::recv(c.fd, buffer, sizeof buffer, 0);
  if (n == 0) {
    c.eof = true;   // a response being written is finished first; anything else ends here
    if (c.state != Connection::Writing) c.closing = true;
    return;
  }
  if (n < 0) {
    if (errno != EAGAIN && errno != EINTR) c.closing = true;   // the browser went away
    return;
  }
  if (c.state != Connection::Reading) return;
  c.in.append(buffer, static_cast<std::size_t>(n));
  const HeadParse head = parseRequestHead(c.in);
  if (head.kind == HeadParse::Incomplete) return;
  HttpResponse r = head.kind == HeadParse::Refused   ? errorResponse(head.status, head.reason)
                   : head.request.method == "GET"    ? site.respond(head.request)
                                                     : errorResponse(405, "only GET is served");
  if (r.status == 405) r.extraHeaders += "Allow: GET\r\n";
  c.queue(responseBytes(r) + (r.stream ? site.nextEvent(c.seen) : ""));   // a stream: the state now
  c.body = r.sharedBody;
  c.state = r.stream ? Connection::Streaming : Connection::Writing;
  c.moved = now;
}

// What `c` has to send, and what it has to send next: a stream the newest state (or now and
// then a comment, so that a vanished browser is found); a whole response, the end of the
// connection. And the time limits.
void sendTo(Connection& c, HttpSite& site, Clock::time_point now) {
  if (!c.closing && !flush(c)) c.closing = true;
  if (!c.closing && c.state == Connection::Streaming && !c.pending()) {
    std::string event = site.nextEvent(c.seen);
    if (!event.empty()) c.queue(event), c.moved = now;
    else if (now - c.moved > std::chrono::seconds(kKeepAliveSeconds)) c.queue(":\n\n"), c.moved = now;
    if (!flush(c)) c.closing = true;
  }
  if (!c.closing && c.state == Connection::Writing && !c.pending()) {
    ::shutdown(c.fd, SHUT_WR);
    c.state = Connection::Draining;
    c.moved = now;
    if (c.eof) c.closing = true;   // the browser closed its side already: nothing to drain
  }
  if (c.state == Connection::Draining && now - c.moved > std::chrono::seconds(2)) c.closing = true;
  if (c.state == Connection::Reading && now - c.opened > std::chrono::seconds(kHeadSeconds)) c.closing = true;
  if (c.pending() && now - c.moved > std::chrono::seconds(kStallSeconds)) c.closing = true;
}

// Sends 503 (as far as the socket takes it at once) and closes.
void refuse(Connection& c) {
  c.queue(responseBytes(errorResponse(503, "too many connections")));
  flush(c);
  c.closing = true;
}

// Every connection waiting to be taken. Past kMaxConnections, a new one replaces the oldest
// connection still waiting for its request, or is refused. Returns false when no more can be
// taken for now (the process is out of file descriptors): the caller waits before trying again.
bool acceptWaiting(int listening, std::vector<std::unique_ptr<Connection>>& connections, Clock::time_point now) {
  for (;;) {
    const int fd = ::accept4(listening, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return errno != EMFILE && errno != ENFILE && errno != ENOBUFS && errno != ENOMEM;
    auto c = std::make_unique<Connection>();
    c->fd = fd;
    c->opened = c->moved = now;
    if (connections.size() >= static_cast<std::size_t>(kMaxConnections)) {
      Connection* oldest = nullptr;
      for (const auto& other : connections)
        if (other->state == Connection::Reading && !other->closing && (!oldest || other->opened < oldest->opened))
          oldest = other.get();
      if (!oldest) {
        refuse(*c);
        continue;
      }
      refuse(*oldest);
      std::erase_if(connections, [](const auto& other) { return other->closing; });
    }
    connections.push_back(std::move(c));
  }
}

// The listening socket on host:port, and the host as a URL writes it.
int listenOn(const std::string& host, int port, std::string& urlHost) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string name = host.empty() ? "127.0.0.1" : host;
  if (int e = ::getaddrinfo(name.c_str(), std::to_string(port).c_str(), &hints, &found); e != 0)
    throw IoError("cannot listen on '" + name + "': " + ::gai_strerror(e));
  std::unique_ptr<addrinfo, void (*)(addrinfo*)> list(found, ::freeaddrinfo);
  int lastErrno = 0;
  for (addrinfo* a = found; a; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      lastErrno = errno;
      continue;
    }
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) == 0 && ::listen(fd, 16) == 0) {
      char text[INET6_ADDRSTRLEN] = "";
      const void* address = a->ai_family == AF_INET6
                                ? static_cast<const void*>(&reinterpret_cast<sockaddr_in6*>(a->ai_addr)->sin6_addr)
                                : static_cast<const void*>(&reinterpret_cast<sockaddr_in*>(a->ai_addr)->sin_addr);
      ::inet_ntop(a->ai_family, address, text, sizeof text);
      urlHost = a->ai_family == AF_INET6 ? "[" + std::string(text) + "]" : std::string(text);
      return fd;
    }
    lastErrno = errno;
    ::close(fd);
  }
  throw IoError("cannot listen on " + name + " port " + std::to_string(port) + ": " + std::strerror(lastErrno));
}

int boundPort(int fd) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  return ntohs(address.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6*>(&address)->sin6_port
                                             : reinterpret_cast<sockaddr_in*>(&address)->sin_port);
}

}  // namespace

HttpServer::HttpServer(const std::string& host, int port, HttpSite& site) : site_(site) {
  listen_ = listenOn(host, port, urlHost_);
  setNonBlocking(listen_);
  port_ = boundPort(listen_);
  int pipe[2];
  if (::pipe2(pipe, O_CLOEXEC | O_NONBLOCK) != 0) {
    ::close(listen_);
    throw IoError(std::string("cannot make the server's wake-up pipe: ") + std::strerror(errno));
  }
  wakeRead_ = pipe[0], wakeWrite_ = pipe[1];
  thread_ = std::thread([this] { run(); });
}

HttpServer::~HttpServer() {
  stopping_ = true;
  notify();
  thread_.join();
  ::close(listen_);
  ::close(wakeRead_);
  ::close(wakeWrite_);
}

void HttpServer::notify() {
  const char byte = 1;
  [[maybe_unused]] ssize_t n = ::write(wakeWrite_, &byte, 1);   // full: a wake-up is pending anyway
}

void HttpServer::run() {
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 10);   // this thread only (Linux); failure: as it was
  std::vector<std::unique_ptr<Connection>> connections;
  std::vector<pollfd> polled;
  Clock::time_point acceptAgain;   // out of file descriptors: the listening socket rests until then
  while (!stopping_) {
    const bool resting = Clock::now() < acceptAgain;
    polled.assign({{listen_, static_cast<short>(resting ? 0 : POLLIN), 0}, {wakeRead_, POLLIN, 0}});
    for (const auto& c : connections)
      polled.push_back({c->fd, static_cast<short>((c->eof ? 0 : POLLIN) | (c->pending() ? POLLOUT : 0)), 0});
    if (::poll(polled.data(), polled.size(), resting ? 100 : 1000) < 0 && errno != EINTR) break;
    const Clock::time_point now = Clock::now();
    if (polled[1].revents & POLLIN) {
      char drain[64];
      while (::read(wakeRead_, drain, sizeof drain) > 0) {
      }
    }
    for (std::size_t i = 0; i < connections.size(); ++i) {
      Connection& c = *connections[i];
      if (polled[i + 2].revents & (POLLERR | POLLNVAL)) c.closing = true;
      if (!c.closing && !c.eof && (polled[i + 2].revents & (POLLIN | POLLHUP))) receiveFrom(c, site_, now);
      sendTo(c, site_, now);
    }
    std::erase_if(connections, [](const auto& c) { return c->closing; });
    if ((polled[0].revents & POLLIN) && !acceptWaiting(listen_, connections, now))
      acceptAgain = now + std::chrono::milliseconds(100);
  }
}

}  // namespace vkrt
