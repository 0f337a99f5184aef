// The platform layer's sockets (host/platform/socket.h), on the system the tests run on:
// Linux, and Windows under Wine. Each test is a promise vkrt view's server or the tev client
// keeps on both: loopback listening and talking, polls that wait as long as they are told and
// wake when they should, a port that a second listener cannot take (Windows' SO_REUSEADDR
// would let it: SO_EXCLUSIVEADDRUSE), no SIGPIPE from a send to a closed peer. Standard C++,
// gtest and the layer only: the Windows build compiles the same file.
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "platform/socket.h"

using namespace vkrt::platform;
using Clock = std::chrono::steady_clock;

namespace {

Socket listening(const std::string& host = "127.0.0.1") {
  SocketFailure failure;
  Socket s = listenTcp(host, 0, 8, failure);
  EXPECT_TRUE(s.valid()) << failure.text;
  return s;
}

Socket connected(int port, const std::string& host = "127.0.0.1") {
  SocketFailure failure;
  Socket s = connectTcp(host, port, 2000, failure);
  EXPECT_TRUE(s.valid()) << failure.text;
  return s;
}

// Polls one socket for reading: whether it became readable within `ms`.
bool readableWithin(const Socket& s, int ms) {
  std::vector<PollItem> items(1);
  items[0].handle = s.native(), items[0].wantRead = true;
  int error = 0;
  const int ready = pollSockets(items, ms, error);
  EXPECT_GE(ready, 0) << socketErrorText(error);
  return ready == 1 && items[0].readable;
}

// The connection waiting on `listener` (non-blocking, as acceptConnection makes it).
Socket accepted(const Socket& listener) {
  EXPECT_TRUE(readableWithin(listener, 2000)) << "no connection came";
  int error = 0;
  Socket s = acceptConnection(listener, error);
  EXPECT_TRUE(s.valid()) << socketErrorText(error);
  return s;
}

std::string receiveAll(const Socket& s, std::size_t size) {
  std::string got;
  char buffer[256];
  while (got.size() < size && readableWithin(s, 2000)) {
    const Transfer t = s.receive(buffer, sizeof buffer);
    if (t.bytes <= 0) break;
    got.append(buffer, static_cast<std::size_t>(t.bytes));
  }
  return got;
}

}  // namespace

TEST(Socket, ListensOnLoopbackConnectsAndTalksBothWays) {
  Socket listener = listening();
  ASSERT_TRUE(listener.setNonBlocking(true));
  const Socket::Name name = listener.localName();
  EXPECT_EQ(name.host, "127.0.0.1");
  EXPECT_FALSE(name.ipv6);
  ASSERT_GT(name.port, 0);   // port 0: a free one was chosen, and is known
  Socket client = connected(name.port);
  Socket server = accepted(listener);
  ASSERT_TRUE(client.valid() && server.valid());
  EXPECT_EQ(client.send("hello", 5).bytes, 5);
  EXPECT_EQ(receiveAll(server, 5), "hello");
  const std::string reply(100000, 'r');   // more than one receive's worth
  std::size_t sent = 0;
  std::string got;
  char buffer[4096];
  while (got.size() < reply.size()) {   // the server's socket does not block: send what it takes, read, again
    if (sent < reply.size()) {
      const Transfer t = server.send(reply.data() + sent, reply.size() - sent);
      ASSERT_TRUE(!t.failed() || t.wouldBlock()) << socketErrorText(t.error);
      if (!t.failed()) sent += static_cast<std::size_t>(t.bytes);
    }
    ASSERT_TRUE(readableWithin(client, 2000));
    const Transfer r = client.receive(buffer, sizeof buffer);
    ASSERT_GT(r.bytes, 0);
    got.append(buffer, static_cast<std::size_t>(r.bytes));
  }
  EXPECT_EQ(got, reply);
  // The end of the stream: a receive of 0 bytes, after the sender shuts its side.
  client.shutdownSending();
  ASSERT_TRUE(readableWithin(server, 2000));
  EXPECT_EQ(server.receive(buffer, sizeof buffer).bytes, 0);
}

TEST(Socket, ListensOnIpv6LoopbackWhereThereIsOne) {
  SocketFailure failure;
  Socket listener = listenTcp("::1", 0, 8, failure);
  if (!listener.valid()) GTEST_SKIP() << "no IPv6 loopback here: " << failure.text;
  const Socket::Name name = listener.localName();
  EXPECT_TRUE(name.ipv6);
  EXPECT_EQ(name.host, "::1");
  ASSERT_TRUE(listener.setNonBlocking(true));
  Socket client = connected(name.port, "::1");
  Socket server = accepted(listener);
  EXPECT_EQ(client.send("six", 3).bytes, 3);
  EXPECT_EQ(receiveAll(server, 3), "six");
}

TEST(Socket, ASecondListenerCannotTakeThePort) {
  Socket first = listening();
  const int port = first.localName().port;
  SocketFailure failure;
  Socket second = listenTcp("127.0.0.1", port, 8, failure);
  EXPECT_FALSE(second.valid()) << "a second socket listens on port " << port << " beside the first";
  EXPECT_FALSE(failure.resolving);
  EXPECT_NE(failure.error, 0);
  EXPECT_FALSE(failure.text.empty());
}

TEST(Socket, AClosedPortRefusesAndAnUnknownHostIsAResolverFailure) {
  int port = 0;
  {
    Socket closed = listening();
    port = closed.localName().port;
  }
  SocketFailure failure;
  EXPECT_FALSE(connectTcp("127.0.0.1", port, 2000, failure).valid());
  EXPECT_FALSE(failure.resolving);
  EXPECT_NE(failure.error, 0);
  EXPECT_FALSE(failure.text.empty());
  failure = {};
  EXPECT_FALSE(listenTcp("not an address", 0, 8, failure).valid());
  EXPECT_TRUE(failure.resolving);
  EXPECT_FALSE(failure.text.empty());
}

TEST(Socket, PollWaitsItsTimeAndNonBlockingReceivesDoNotWait) {
  Socket listener = listening();
  ASSERT_TRUE(listener.setNonBlocking(true));
  Socket client = connected(listener.localName().port);
  Socket server = accepted(listener);
  const auto t0 = Clock::now();
  EXPECT_FALSE(readableWithin(server, 200));   // nothing sent
  EXPECT_GE(Clock::now() - t0, std::chrono::milliseconds(150));
  char byte;
  const Transfer t = server.receive(&byte, 1);
  EXPECT_TRUE(t.failed());
  EXPECT_TRUE(t.wouldBlock()) << socketErrorText(t.error);
  int error = 0;
  EXPECT_FALSE(acceptConnection(listener, error).valid());   // no other connection waits
  EXPECT_TRUE(isWouldBlock(error)) << socketErrorText(error);
  // Several sockets at once: only the one written to is readable.
  std::vector<PollItem> items(2);
  items[0].handle = listener.native(), items[0].wantRead = true;
  items[1].handle = server.native(), items[1].wantRead = true, items[1].wantWrite = true;
  EXPECT_EQ(pollSockets(items, 1000, error), 1);   // the server can write at once
  EXPECT_FALSE(items[0].readable);
  EXPECT_FALSE(items[1].readable);
  EXPECT_TRUE(items[1].writable);
  items[1].wantWrite = false;
  client.send("x", 1);
  EXPECT_EQ(pollSockets(items, 2000, error), 1);
  EXPECT_FALSE(items[0].readable);
  EXPECT_TRUE(items[1].readable);
}

TEST(Socket, AWakerWakesAPollFromAnotherThread) {
  PollWaker waker;
  std::vector<PollItem> items(1);
  items[0].handle = waker.handle(), items[0].wantRead = true;
  int error = 0;
  EXPECT_EQ(pollSockets(items, 50, error), 0);   // nothing yet
  const auto t0 = Clock::now();
  std::thread other([&waker] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    waker.notify();
    waker.notify();   // twice: one wake-up, drained at once
  });
  EXPECT_EQ(pollSockets(items, 5000, error), 1);
  EXPECT_TRUE(items[0].readable);
  EXPECT_LT(Clock::now() - t0, std::chrono::milliseconds(4000));
  other.join();
  waker.drain();
  EXPECT_EQ(pollSockets(items, 50, error), 0);   // drained: quiet again
  EXPECT_FALSE(items[0].readable);
}

TEST(Socket, SendingToAClosedPeerFailsAndRaisesNoSignal) {
  Socket listener = listening();
  ASSERT_TRUE(listener.setNonBlocking(true));
  Socket client = connected(listener.localName().port);
  accepted(listener).close();   // the peer goes away at once
  // The first sends may still be taken; then one fails (POSIX: EPIPE or ECONNRESET, with no
  // SIGPIPE to end this process; Windows: WSAECONNRESET or WSAECONNABORTED).
  const std::string data(4096, 'd');
  Transfer t;
  for (int i = 0; i < 1000 && !t.failed(); ++i) {
    t = client.send(data.data(), data.size());
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_TRUE(t.failed());
  EXPECT_FALSE(t.wouldBlock());
  EXPECT_FALSE(socketErrorText(t.error).empty());
}

TEST(Socket, ThisMachineHasAName) { EXPECT_FALSE(hostName().empty()); }
