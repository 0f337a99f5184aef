// TCP sockets, the same on POSIX and Windows: what vkrt view's server (net/http_server.h)
// and the tev client (net/tev_display.h) need. A Socket closes itself; listening takes the
// first address of a name that can be bound; connecting gives each address a time limit;
// sockets are never inherited by a child process, and a send to a peer that has gone away
// fails with an error instead of raising SIGPIPE. Errors are the system's numbers (errno;
// WSAGetLastError on Windows), worded by socketErrorText. Windows: Winsock 2, started once
// by the first call that needs it; a listening socket is bound with SO_EXCLUSIVEADDRUSE (its
// SO_REUSEADDR would let another program bind the same port), POSIX's with SO_REUSEADDR (a
// port left in TIME_WAIT by an earlier run can be listened on again at once).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vkrt::platform {

#ifdef _WIN32
using NativeSocket = std::uintptr_t;   // SOCKET
inline constexpr NativeSocket kNoSocket = ~NativeSocket{0};   // INVALID_SOCKET
#else
using NativeSocket = int;
inline constexpr NativeSocket kNoSocket = -1;
#endif

// The words for a socket error number (strerror; Windows: FormatMessage, in UTF-8).
std::string socketErrorText(int error);

// What one send or receive did: `bytes` moved (0 from receive: the peer closed its side), or
// bytes < 0 and `error` set. A call cut short by a signal is made again.
struct Transfer {
  std::ptrdiff_t bytes = 0;
  int error = 0;
  bool failed() const { return bytes < 0; }
  // Failed only because a non-blocking socket could not move anything now.
  bool wouldBlock() const;
};

// Why listening or connecting failed: while finding the host's addresses (the resolver's
// words), or at the last address tried (the system's error).
struct SocketFailure {
  bool resolving = false;
  int error = 0;      // the last socket error (0 while resolving)
  std::string text;   // in words
};

class Socket {
 public:
  Socket() = default;
  explicit Socket(NativeSocket handle) : handle_(handle) {}
  ~Socket() { close(); }
  Socket(Socket&& other) noexcept : handle_(other.release()) {}
  Socket& operator=(Socket&& other) noexcept;
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;

  bool valid() const { return handle_ != kNoSocket; }
  NativeSocket native() const { return handle_; }
  NativeSocket release() {
    const NativeSocket h = handle_;
    handle_ = kNoSocket;
    return h;
  }
  void close();

  // Sends or receives, as far as the socket takes it (all of it, for a blocking socket's send
  // of a small buffer; at least one byte, when it does not fail).
  Transfer send(const void* data, std::size_t size) const;
  Transfer receive(void* data, std::size_t size) const;
  // Ends sending (the peer reads the end of the stream once it has what was sent), or both
  // directions (a send or receive waiting on another thread returns). Failures are ignored.
  void shutdownSending() const;
  void shutdownBoth() const;
  // Non-blocking: send, receive and accept return wouldBlock() instead of waiting. True when set.
  bool setNonBlocking(bool on) const;

  // The address it is bound to: `host` numeric ("127.0.0.1", "::1"), `ipv6`, and its port.
  struct Name {
    std::string host;
    bool ipv6 = false;
    int port = 0;
  };
  Name localName() const;

 private:
  NativeSocket handle_ = kNoSocket;
};

// A socket listening on `host` (a name or a numeric address) and `port` (0: a free one), with
// room for `backlog` connections not yet accepted; invalid with `failure` set when no address
// of the host can be bound (not this machine's, the port taken).
Socket listenTcp(const std::string& host, int port, int backlog, SocketFailure& failure);

// The next connection waiting on a listening socket, itself non-blocking; invalid with `error`
// set when there is none (wouldBlockError) or it cannot be taken (outOfResources).
Socket acceptConnection(const Socket& listening, int& error);

// A blocking socket connected to `host`:`port`, trying each of its addresses in turn and
// giving each at most `timeoutMs`; invalid with `failure` set when none answers.
Socket connectTcp(const std::string& host, int port, int timeoutMs, SocketFailure& failure);

// Whether an error means "nothing to do now" on a non-blocking socket, and whether it means
// the process has run out of sockets or memory (accepting must wait until some are closed).
bool isWouldBlock(int error);
bool isOutOfResources(int error);

// Waiting for several sockets at once. `readable` includes a connection waiting to be
// accepted and the peer's end of stream; `hangup` the connection closed; `failed` an error
// on the socket or a handle that is not one.
struct PollItem {
  NativeSocket handle = kNoSocket;
  bool wantRead = false, wantWrite = false;
  bool readable = false, writable = false, hangup = false, failed = false;   // set by pollSockets
};
// Waits at most `timeoutMs` (-1: no limit) until one of `items` is ready: how many are, 0 when
// none (the time ran out, or a signal came), -1 with `error` set when waiting failed.
int pollSockets(std::vector<PollItem>& items, int timeoutMs, int& error);

// A handle that pollSockets sees readable once notify() has been called, until drain(): wakes
// a thread waiting in pollSockets from any other. POSIX: a pipe; Windows: a loopback UDP
// socket that sends itself a byte (WSAPoll waits on sockets only). Throws std::runtime_error
// (the system's words) when it cannot be made.
class PollWaker {
 public:
  PollWaker();
  ~PollWaker();
  PollWaker(const PollWaker&) = delete;
  PollWaker& operator=(const PollWaker&) = delete;
  NativeSocket handle() const { return read_; }
  void notify();   // never blocks: when one is pending already, that wakes the poll
  void drain();

 private:
  NativeSocket read_ = kNoSocket, write_ = kNoSocket;
};

// This machine's name ("" when it has none to give).
std::string hostName();

}  // namespace vkrt::platform
