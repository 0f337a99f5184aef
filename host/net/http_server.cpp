// The server's loop: http_server.h.
#include "net/http_server.h"

#include <chrono>
#include <memory>
#include <vector>

#include "platform/socket.h"
#include "platform/thread_priority.h"
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

struct Connection {
  platform::Socket socket;
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
    const platform::Transfer sent = c.socket.send(from, left);
    if (sent.failed()) return sent.wouldBlock();
    (head ? c.sent : c.bodySent) += static_cast<std::size_t>(sent.bytes);
    c.moved = Clock::now();
  }
  return true;
}

// What the browser sent: the request's head, answered once whole (or refused); after it, a
// stream's or a finished request's further bytes are read and dropped.
void receiveFrom(Connection& c, HttpSite& site, Clock::time_point now) {
  char buffer[4096];
  const platform::Transfer received = c.socket.receive(buffer, sizeof buffer);
  if (received.bytes == 0) {
    c.eof = true;   // a response being written is finished first; anything else ends here
    if (c.state != Connection::Writing) c.closing = true;
    return;
  }
  if (received.failed()) {
    if (!received.wouldBlock()) c.closing = true;   // the browser went away
    return;
  }
  if (c.state != Connection::Reading) return;
  c.in.append(buffer, static_cast<std::size_t>(received.bytes));
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
    c.socket.shutdownSending();
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
bool acceptWaiting(const platform::Socket& listening, std::vector<std::unique_ptr<Connection>>& connections,
                   Clock::time_point now) {
  for (;;) {
    int error = 0;
    platform::Socket accepted = platform::acceptConnection(listening, error);
    if (!accepted.valid()) return !platform::isOutOfResources(error);
    auto c = std::make_unique<Connection>();
    c->socket = std::move(accepted);
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
platform::Socket listenOn(const std::string& host, int port, std::string& urlHost) {
  const std::string name = host.empty() ? "127.0.0.1" : host;
  platform::SocketFailure failure;
  platform::Socket s = platform::listenTcp(name, port, 16, failure);
  if (!s.valid() && failure.resolving) throw IoError("cannot listen on '" + name + "': " + failure.text);
  if (!s.valid()) throw IoError("cannot listen on " + name + " port " + std::to_string(port) + ": " + failure.text);
  const platform::Socket::Name bound = s.localName();
  urlHost = bound.ipv6 ? "[" + bound.host + "]" : bound.host;
  return s;
}

}  // namespace

HttpServer::HttpServer(const std::string& host, int port, HttpSite& site) : site_(site) {
  listen_ = listenOn(host, port, urlHost_);
  listen_.setNonBlocking(true);
  port_ = listen_.localName().port;
  try {
    wake_ = std::make_unique<platform::PollWaker>();
  } catch (const std::exception& e) {
    throw IoError(std::string("cannot make the server's wake-up pipe: ") + e.what());
  }
  thread_ = std::thread([this] { run(); });
}

HttpServer::~HttpServer() {
  stopping_ = true;
  notify();
  thread_.join();
}

void HttpServer::notify() { wake_->notify(); }

void HttpServer::run() {
  platform::lowerThisThreadsPriority();
  std::vector<std::unique_ptr<Connection>> connections;
  std::vector<platform::PollItem> polled;
  Clock::time_point acceptAgain;   // out of file descriptors: the listening socket rests until then
  while (!stopping_) {
    const bool resting = Clock::now() < acceptAgain;
    polled.assign(2, {});
    polled[0].handle = listen_.native(), polled[0].wantRead = !resting;
    polled[1].handle = wake_->handle(), polled[1].wantRead = true;
    for (const auto& c : connections) {
      platform::PollItem& item = polled.emplace_back();
      item.handle = c->socket.native(), item.wantRead = !c->eof, item.wantWrite = c->pending();
    }
    int error = 0;
    if (platform::pollSockets(polled, resting ? 100 : 1000, error) < 0) break;
    const Clock::time_point now = Clock::now();
    if (polled[1].readable) wake_->drain();
    for (std::size_t i = 0; i < connections.size(); ++i) {
      Connection& c = *connections[i];
      const platform::PollItem& item = polled[i + 2];
      if (item.failed) c.closing = true;
      if (!c.closing && !c.eof && (item.readable || item.hangup)) receiveFrom(c, site_, now);
      sendTo(c, site_, now);
    }
    std::erase_if(connections, [](const auto& c) { return c->closing; });
    if (polled[0].readable && !acceptWaiting(listen_, connections, now))
      acceptAgain = now + std::chrono::milliseconds(100);
  }
}

}  // namespace vkrt
