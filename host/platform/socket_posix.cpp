// socket.h on POSIX: BSD sockets, poll() and a pipe to wake it. Linux's SOCK_CLOEXEC,
// SOCK_NONBLOCK, accept4 and pipe2 make a descriptor and its flags in one call; elsewhere
// (macOS) fcntl sets them after, and SO_NOSIGPIPE stands for MSG_NOSIGNAL.
#include "platform/socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace vkrt::platform {
namespace {

#ifdef SOCK_CLOEXEC
constexpr int kSocketCloexec = SOCK_CLOEXEC;
#else
constexpr int kSocketCloexec = 0;
#endif
#ifdef MSG_NOSIGNAL
constexpr int kNoSignal = MSG_NOSIGNAL;
#else
constexpr int kNoSignal = 0;   // SO_NOSIGPIPE, set on each socket made (newSocket)
#endif

// A socket of `a`'s kind, not inherited by a child process and, off Linux, raising no SIGPIPE.
int newSocket(const addrinfo* a) {
  const int fd = ::socket(a->ai_family, a->ai_socktype | kSocketCloexec, a->ai_protocol);
  if (fd < 0) return fd;
#ifndef SOCK_CLOEXEC
  ::fcntl(fd, F_SETFD, FD_CLOEXEC);
#endif
#if !defined(MSG_NOSIGNAL) && defined(SO_NOSIGPIPE)
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_NOSIGPIPE, &one, sizeof one);
#endif
  return fd;
}

bool setFlag(int fd, int flag, bool on) {
  const int flags = ::fcntl(fd, F_GETFL);
  return flags >= 0 && ::fcntl(fd, F_SETFL, on ? flags | flag : flags & ~flag) == 0;
}

using AddressList = std::unique_ptr<addrinfo, void (*)(addrinfo*)>;

// The addresses of host:port for a stream socket, or null with `failure` set.
AddressList resolve(const std::string& host, int port, int flags, SocketFailure& failure) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = flags;
  addrinfo* found = nullptr;
  if (const int e = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found); e != 0) {
    failure = {true, 0, ::gai_strerror(e)};
    return {nullptr, ::freeaddrinfo};
  }
  return {found, ::freeaddrinfo};
}

}  // namespace

std::string socketErrorText(int error) { return std::strerror(error); }

bool isWouldBlock(int error) { return error == EAGAIN || error == EWOULDBLOCK; }

bool isOutOfResources(int error) { return error == EMFILE || error == ENFILE || error == ENOBUFS || error == ENOMEM; }

void Socket::close() {
  if (handle_ >= 0) ::close(handle_);
  handle_ = kNoSocket;
}

Transfer Socket::send(const void* data, std::size_t size) const {
  for (;;) {
    const ssize_t n = ::send(handle_, data, size, kNoSignal);
    if (n >= 0) return {n, 0};
    if (errno != EINTR) return {-1, errno};
  }
}

Transfer Socket::receive(void* data, std::size_t size) const {
  for (;;) {
    const ssize_t n = ::recv(handle_, data, size, 0);
    if (n >= 0) return {n, 0};
    if (errno != EINTR) return {-1, errno};
  }
}

void Socket::shutdownSending() const { ::shutdown(handle_, SHUT_WR); }

void Socket::shutdownBoth() const { ::shutdown(handle_, SHUT_RDWR); }

bool Socket::setNonBlocking(bool on) const { return setFlag(handle_, O_NONBLOCK, on); }

Socket::Name Socket::localName() const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  Name name;
  if (::getsockname(handle_, reinterpret_cast<sockaddr*>(&address), &length) != 0) return name;
  char text[INET6_ADDRSTRLEN] = "";
  name.ipv6 = address.ss_family == AF_INET6;
  if (name.ipv6) {
    const auto* a = reinterpret_cast<const sockaddr_in6*>(&address);
    ::inet_ntop(AF_INET6, &a->sin6_addr, text, sizeof text);
    name.port = ntohs(a->sin6_port);
  } else {
    const auto* a = reinterpret_cast<const sockaddr_in*>(&address);
    ::inet_ntop(AF_INET, &a->sin_addr, text, sizeof text);
    name.port = ntohs(a->sin_port);
  }
  name.host = text;
  return name;
}

Socket listenTcp(const std::string& host, int port, int backlog, SocketFailure& failure) {
  const AddressList found = resolve(host, port, AI_PASSIVE | AI_NUMERICSERV, failure);
  if (!found) return {};
  int lastErrno = 0;
  for (const addrinfo* a = found.get(); a; a = a->ai_next) {
    Socket s(newSocket(a));
    if (!s.valid()) {
      lastErrno = errno;
      continue;
    }
    const int one = 1;
    ::setsockopt(s.native(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(s.native(), a->ai_addr, a->ai_addrlen) == 0 && ::listen(s.native(), backlog) == 0) return s;
    lastErrno = errno;
  }
  failure = {false, lastErrno, std::strerror(lastErrno)};
  return {};
}

Socket acceptConnection(const Socket& listening, int& error) {
#ifdef __linux__
  const int fd = ::accept4(listening.native(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
#else
  const int fd = ::accept(listening.native(), nullptr, nullptr);
  if (fd >= 0) ::fcntl(fd, F_SETFD, FD_CLOEXEC), setFlag(fd, O_NONBLOCK, true);
#endif
  error = fd < 0 ? errno : 0;
  Socket s(fd);
#if !defined(MSG_NOSIGNAL) && defined(SO_NOSIGPIPE)
  const int one = 1;
  if (s.valid()) ::setsockopt(fd, SOL_SOCKET, SO_NOSIGPIPE, &one, sizeof one);
#endif
  return s;
}

Socket connectTcp(const std::string& host, int port, int timeoutMs, SocketFailure& failure) {
  const AddressList found = resolve(host, port, 0, failure);
  if (!found) return {};
  int error = 0;
  for (const addrinfo* a = found.get(); a; a = a->ai_next) {
    Socket s(newSocket(a));
    if (!s.valid() || !s.setNonBlocking(true)) {
      error = errno;
      continue;
    }
    error = 0;
    if (::connect(s.native(), a->ai_addr, a->ai_addrlen) != 0) {
      if (errno != EINPROGRESS) {
        error = errno;
      } else {
        pollfd w{s.native(), POLLOUT, 0};
        socklen_t n = sizeof error;
        if (::poll(&w, 1, timeoutMs) != 1) error = ETIMEDOUT;
        else ::getsockopt(s.native(), SOL_SOCKET, SO_ERROR, &error, &n);
      }
    }
    if (error == 0 && s.setNonBlocking(false)) return s;
    if (error == 0) error = errno;
  }
  failure = {false, error ? error : ECONNREFUSED, std::strerror(error ? error : ECONNREFUSED)};
  return {};
}

int pollSockets(std::vector<PollItem>& items, int timeoutMs, int& error) {
  std::vector<pollfd> polled;
  polled.reserve(items.size());
  for (const PollItem& item : items)
    polled.push_back({item.handle, static_cast<short>((item.wantRead ? POLLIN : 0) | (item.wantWrite ? POLLOUT : 0)), 0});
  const int ready = ::poll(polled.data(), polled.size(), timeoutMs);
  error = ready < 0 ? errno : 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const short got = ready > 0 ? polled[i].revents : 0;
    items[i].readable = got & POLLIN;
    items[i].writable = got & POLLOUT;
    items[i].hangup = got & POLLHUP;
    items[i].failed = got & (POLLERR | POLLNVAL);
  }
  if (ready < 0 && error == EINTR) return 0;
  return ready;
}

PollWaker::PollWaker() {
  int pipe[2];
#ifdef __linux__
  const bool made = ::pipe2(pipe, O_CLOEXEC | O_NONBLOCK) == 0;
#else
  const bool made = ::pipe(pipe) == 0;
  if (made)
    for (int fd : pipe) ::fcntl(fd, F_SETFD, FD_CLOEXEC), setFlag(fd, O_NONBLOCK, true);
#endif
  if (!made) throw std::runtime_error(std::strerror(errno));
  read_ = pipe[0], write_ = pipe[1];
}

PollWaker::~PollWaker() {
  ::close(read_);
  ::close(write_);
}

void PollWaker::notify() {
  const char byte = 1;
  [[maybe_unused]] ssize_t n = ::write(write_, &byte, 1);   // full: a wake-up is pending anyway
}

void PollWaker::drain() {
  char drained[64];
  while (::read(read_, drained, sizeof drained) > 0) {
  }
}

std::string hostName() {
  char name[256] = "";
  if (::gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

}  // namespace vkrt::platform
