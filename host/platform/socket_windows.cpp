// socket.h on Windows: Winsock 2 (started once, on first use), WSAPoll, and a loopback UDP
// socket that sends itself a byte to wake a poll (WSAPoll waits on sockets only). Sockets
// are made not inheritable; Windows has no SIGPIPE, so a send to a closed peer fails with
// WSAECONNRESET or WSAESHUTDOWN as it is. Names are resolved with GetAddrInfoW (UTF-8 in).
#include "platform/socket.h"

#ifndef WIN32_LEAN_AND_MEAN
#  define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#  define NOMINMAX
#endif
#include <winsock2.h>
#include <ws2tcpip.h>
#include <windows.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "platform/utf8.h"

namespace vkrt::platform {
namespace {

// Winsock, started by the first call that needs it; never cleaned up (the process's end does).
void startWinsock() {
  static const int started = [] {
    WSADATA data;
    return ::WSAStartup(MAKEWORD(2, 2), &data);
  }();
  (void)started;   // a failure shows as WSANOTINITIALISED from the call that follows
}

SOCKET newSocket(int family, int type, int protocol) {
  startWinsock();
  return ::WSASocketW(family, type, protocol, nullptr, 0, WSA_FLAG_OVERLAPPED | WSA_FLAG_NO_HANDLE_INHERIT);
}

using AddressList = std::unique_ptr<ADDRINFOW, void (*)(ADDRINFOW*)>;

void freeAddresses(ADDRINFOW* list) { ::FreeAddrInfoW(list); }

AddressList resolve(const std::string& host, int port, int flags, SocketFailure& failure) {
  startWinsock();
  ADDRINFOW hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_protocol = IPPROTO_TCP;
  hints.ai_flags = flags;
  ADDRINFOW* found = nullptr;
  const std::wstring service = std::to_wstring(port);
  if (const int e = ::GetAddrInfoW(wideFromUtf8(host).c_str(), service.c_str(), &hints, &found); e != 0) {
    failure = {true, 0, socketErrorText(e)};
    return {nullptr, freeAddresses};
  }
  return {found, freeAddresses};
}

}  // namespace

std::string socketErrorText(int error) {
  wchar_t* text = nullptr;
  const DWORD n = ::FormatMessageW(
      FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr,
      static_cast<DWORD>(error), 0, reinterpret_cast<wchar_t*>(&text), 0, nullptr);
  std::wstring words = n ? std::wstring(text, n) : L"error " + std::to_wstring(error);
  if (text) ::LocalFree(text);
  while (!words.empty() && (words.back() == L'\n' || words.back() == L'\r' || words.back() == L'.'))
    words.pop_back();
  return utf8FromWide(words);
}

bool isWouldBlock(int error) { return error == WSAEWOULDBLOCK; }

bool isOutOfResources(int error) { return error == WSAEMFILE || error == WSAENOBUFS; }

void Socket::close() {
  if (handle_ != kNoSocket) ::closesocket(static_cast<SOCKET>(handle_));
  handle_ = kNoSocket;
}

Transfer Socket::send(const void* data, std::size_t size) const {
  const int chunk = static_cast<int>(std::min<std::size_t>(size, 1 << 30));
  const int n = ::send(static_cast<SOCKET>(handle_), static_cast<const char*>(data), chunk, 0);
  if (n == SOCKET_ERROR) return {-1, ::WSAGetLastError()};
  return {n, 0};
}

Transfer Socket::receive(void* data, std::size_t size) const {
  const int chunk = static_cast<int>(std::min<std::size_t>(size, 1 << 30));
  const int n = ::recv(static_cast<SOCKET>(handle_), static_cast<char*>(data), chunk, 0);
  if (n == SOCKET_ERROR) return {-1, ::WSAGetLastError()};
  return {n, 0};
}

void Socket::shutdownSending() const { ::shutdown(static_cast<SOCKET>(handle_), SD_SEND); }

void Socket::shutdownBoth() const { ::shutdown(static_cast<SOCKET>(handle_), SD_BOTH); }

bool Socket::setNonBlocking(bool on) const {
  u_long mode = on ? 1 : 0;
  return ::ioctlsocket(static_cast<SOCKET>(handle_), FIONBIO, &mode) == 0;
}

Socket::Name Socket::localName() const {
  sockaddr_storage address{};
  int length = sizeof address;
  Name name;
  if (::getsockname(static_cast<SOCKET>(handle_), reinterpret_cast<sockaddr*>(&address), &length) != 0) return name;
  char text[INET6_ADDRSTRLEN] = "";
  name.ipv6 = address.ss_family == AF_INET6;
  if (name.ipv6) {
    auto* a = reinterpret_cast<sockaddr_in6*>(&address);
    ::inet_ntop(AF_INET6, &a->sin6_addr, text, sizeof text);
    name.port = ntohs(a->sin6_port);
  } else {
    auto* a = reinterpret_cast<sockaddr_in*>(&address);
    ::inet_ntop(AF_INET, &a->sin_addr, text, sizeof text);
    name.port = ntohs(a->sin_port);
  }
  name.host = text;
  return name;
}

Socket listenTcp(const std::string& host, int port, int backlog, SocketFailure& failure) {
  const AddressList found = resolve(host, port, AI_PASSIVE | AI_NUMERICSERV, failure);
  if (!found) return {};
  int lastError = 0;
  for (const ADDRINFOW* a = found.get(); a; a = a->ai_next) {
    Socket s(newSocket(a->ai_family, a->ai_socktype, a->ai_protocol));
    if (!s.valid()) {
      lastError = ::WSAGetLastError();
      continue;
    }
    // Not SO_REUSEADDR: on Windows it lets another socket bind the same port, and take its
    // connections. A port in TIME_WAIT can be bound again without it.
    const BOOL one = TRUE;
    ::setsockopt(static_cast<SOCKET>(s.native()), SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<const char*>(&one),
                 sizeof one);
    if (::bind(static_cast<SOCKET>(s.native()), a->ai_addr, static_cast<int>(a->ai_addrlen)) == 0 &&
        ::listen(static_cast<SOCKET>(s.native()), backlog) == 0)
      return s;
    lastError = ::WSAGetLastError();
  }
  failure = {false, lastError, socketErrorText(lastError)};
  return {};
}

Socket acceptConnection(const Socket& listening, int& error) {
  Socket s(::accept(static_cast<SOCKET>(listening.native()), nullptr, nullptr));
  error = s.valid() ? 0 : ::WSAGetLastError();
  if (s.valid()) {
    ::SetHandleInformation(reinterpret_cast<HANDLE>(s.native()), HANDLE_FLAG_INHERIT, 0);
    s.setNonBlocking(true);
  }
  return s;
}

Socket connectTcp(const std::string& host, int port, int timeoutMs, SocketFailure& failure) {
  const AddressList found = resolve(host, port, 0, failure);
  if (!found) return {};
  int error = 0;
  for (const ADDRINFOW* a = found.get(); a; a = a->ai_next) {
    Socket s(newSocket(a->ai_family, a->ai_socktype, a->ai_protocol));
    if (!s.valid() || !s.setNonBlocking(true)) {
      error = ::WSAGetLastError();
      continue;
    }
    error = 0;
    const auto handle = static_cast<SOCKET>(s.native());
    if (::connect(handle, a->ai_addr, static_cast<int>(a->ai_addrlen)) != 0) {
      error = ::WSAGetLastError();
      if (error == WSAEWOULDBLOCK) {
        // select, not WSAPoll: before Windows 10 2004, WSAPoll did not report a refused connect.
        fd_set writable, failed;
        FD_ZERO(&writable);
        FD_ZERO(&failed);
        FD_SET(handle, &writable);
        FD_SET(handle, &failed);
        timeval limit{timeoutMs / 1000, (timeoutMs % 1000) * 1000};
        const int ready = ::select(0, nullptr, &writable, &failed, &limit);
        int n = sizeof error;
        if (ready <= 0) error = WSAETIMEDOUT;
        else if (::getsockopt(handle, SOL_SOCKET, SO_ERROR, reinterpret_cast<char*>(&error), &n) != 0 ||
                 (error == 0 && FD_ISSET(handle, &failed)))
          error = error ? error : WSAECONNREFUSED;
      }
    }
    if (error == 0 && s.setNonBlocking(false)) return s;
    if (error == 0) error = ::WSAGetLastError();
  }
  failure = {false, error ? error : WSAECONNREFUSED, socketErrorText(error ? error : WSAECONNREFUSED)};
  return {};
}

int pollSockets(std::vector<PollItem>& items, int timeoutMs, int& error) {
  std::vector<WSAPOLLFD> polled;
  polled.reserve(items.size());
  // POLLRDNORM and POLLWRNORM, not POLLIN (which holds POLLRDBAND: WSAPoll refuses it for TCP).
  for (const PollItem& item : items)
    polled.push_back({static_cast<SOCKET>(item.handle),
                      static_cast<SHORT>((item.wantRead ? POLLRDNORM : 0) | (item.wantWrite ? POLLWRNORM : 0)), 0});
  const int ready = ::WSAPoll(polled.data(), static_cast<ULONG>(polled.size()), timeoutMs);
  error = ready == SOCKET_ERROR ? ::WSAGetLastError() : 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const SHORT got = ready > 0 ? polled[i].revents : 0;
    // The peer's end of stream is readable, as poll() says on POSIX: WSAPoll may say POLLHUP alone.
    items[i].readable = got & (POLLRDNORM | POLLHUP);
    items[i].writable = got & POLLWRNORM;
    items[i].hangup = got & POLLHUP;
    items[i].failed = got & (POLLERR | POLLNVAL);
  }
  return ready == SOCKET_ERROR ? -1 : ready;
}

PollWaker::PollWaker() {
  // One UDP socket on 127.0.0.1, connected to itself: notify() sends it a byte, drain() reads.
  const SOCKET s = newSocket(AF_INET, SOCK_DGRAM, IPPROTO_UDP);
  if (s == INVALID_SOCKET) throw std::runtime_error(socketErrorText(::WSAGetLastError()));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  int length = sizeof address;
  u_long nonBlocking = 1;
  if (::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length) != 0 ||
      ::connect(s, reinterpret_cast<sockaddr*>(&address), length) != 0 || ::ioctlsocket(s, FIONBIO, &nonBlocking) != 0) {
    const int error = ::WSAGetLastError();
    ::closesocket(s);
    throw std::runtime_error(socketErrorText(error));
  }
  read_ = write_ = s;
}

PollWaker::~PollWaker() { ::closesocket(static_cast<SOCKET>(read_)); }

void PollWaker::notify() {
  const char byte = 1;
  ::send(static_cast<SOCKET>(write_), &byte, 1, 0);   // full: a wake-up is pending anyway
}

void PollWaker::drain() {
  char drained[64];
  while (::recv(static_cast<SOCKET>(read_), drained, sizeof drained, 0) > 0) {
  }
}

std::string hostName() {
  startWinsock();
  wchar_t name[256] = L"";
  if (::GetHostNameW(name, 255) != 0) return "";
  return utf8FromWide(name);
}

}  // namespace vkrt::platform
