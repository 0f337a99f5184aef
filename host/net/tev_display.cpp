// The render shown in tev over its network protocol (net/tev_display.h).
#include "net/tev_display.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "util/errors.h"
#include "util/text.h"   // echoed

namespace vkrt {

namespace {

constexpr int kTile = 128;               // tevclient's tiles
constexpr std::uint8_t kCreateImage = 4;  // tev's IpcPacket::EType
constexpr std::uint8_t kUpdateImage = 6;  // (version 3)
constexpr double kConnectSeconds = 2.0;
// The longest a wait for room to send goes without looking whether finish() gave up.
constexpr int kSendPollMs = 100;
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 25;   // 32 Mpixels: 384 MB of float RGB kept

struct Packet {
  std::vector<std::uint8_t> bytes = std::vector<std::uint8_t>(4, 0);   // the length, filled by done()
  template <class T>
  void put(T v) {   // little-endian, as every machine vkrt runs on stores it
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof v);
  }
  void text(const std::string& s) {
    bytes.insert(bytes.end(), s.begin(), s.end());
    bytes.push_back(0);
  }
  std::vector<std::uint8_t> done() {
    const auto n = static_cast<std::uint32_t>(bytes.size());
    std::memcpy(bytes.data(), &n, 4);
    return std::move(bytes);
  }
};

}  // namespace

DisplayAddress parseDisplayAddress(const std::string& text) {
  const std::size_t colon = text.rfind(':');
  auto bad = [&](const std::string& why) {
    return UsageError("--display-server expects HOST:PORT (tev listens on localhost:14158), got '" + echoed(text) +
                      "': " + why);
  };
  if (colon == std::string::npos || colon == 0) throw bad("no host before a ':'");
  DisplayAddress a;
  a.host = text.substr(0, colon);
  if (a.host.size() > 2 && a.host.front() == '[' && a.host.back() == ']') a.host = a.host.substr(1, a.host.size() - 2);
  const std::string port = text.substr(colon + 1);
  if (port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos)
    throw bad("the port is not a number");
  a.port = std::stoi(port);
  if (a.port < 1 || a.port > 65535) throw bad("the port is not within 1 to 65535");
  return a;
}

std::vector<std::uint8_t> tevCreateImage(const std::string& name, int width, int height) {
  Packet p;
  p.put(kCreateImage);
  p.put(std::uint8_t{1});   // grab focus: the new render comes to the front
  p.text(name);
  p.put(std::int32_t{width});
  p.put(std::int32_t{height});
  p.put(std::int32_t{3});
  for (const char* c : {"R", "G", "B"}) p.text(c);
  return p.done();
}

std::vector<std::uint8_t> tevUpdateImage(const std::string& name, const RadianceImage& image, int x0, int y0, int width,
                                         int rows) {
  Packet p;
  p.put(kUpdateImage);
  p.put(std::uint8_t{0});   // an update does not take the focus
  p.text(name);
  p.put(std::int32_t{3});
  for (const char* c : {"R", "G", "B"}) p.text(c);
  p.put(std::int32_t{x0});
  p.put(std::int32_t{y0});
  p.put(std::int32_t{width});
  p.put(std::int32_t{rows});
  for (std::int64_t offset : {0, 1, 2}) p.put(offset);   // the channels interleaved: R G B R G B ...
  for (int c = 0; c < 3; ++c) p.put(std::int64_t{3});
  const std::size_t row = static_cast<std::size_t>(width) * 3 * sizeof(float);
  for (int y = y0; y < y0 + rows; ++y) {
    const auto* from = reinterpret_cast<const std::uint8_t*>(image.pixel(x0, y));
    p.bytes.insert(p.bytes.end(), from, from + row);
  }
  return p.done();
}

std::vector<std::vector<std::uint8_t>> tevTiles(const std::string& name, const RadianceImage& image, int y0, int y1) {
  std::vector<std::vector<std::uint8_t>> out;
  for (int ty = y0 / kTile * kTile; ty < std::min(y1, image.height); ty += kTile)
    for (int tx = 0; tx < image.width; tx += kTile)
      out.push_back(tevUpdateImage(name, image, tx, ty, std::min(kTile, image.width - tx), std::min(kTile, image.height - ty)));
  return out;
}

TevDisplay::TevDisplay(DisplayAddress address, bool quiet) : address_(std::move(address)), quiet_(quiet) {
  thread_ = std::thread([this] { run(); });
}

TevDisplay::~TevDisplay() { finish(); }

void TevDisplay::begin(const std::string& name, int width, int height) {
  if (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > kMaxPixels) {
    // The display keeps the image whole; a streamed render of this size does not.
    warn(name + " is " + std::to_string(width) + "x" + std::to_string(height) + ", more than the " +
         std::to_string(kMaxPixels >> 20) + " Mpixels shown");
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (broken_) return;
  if (!images_.empty()) images_.back().whole = true;   // the render before is over: sent whole
  Pending p;
  p.name = name;
  p.image = RadianceImage(width, height);
  images_.push_back(std::move(p));
  wake_.notify_all();
}

void TevDisplay::update(int y0, const RadianceImage& rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (broken_ || images_.empty()) return;
  Pending& p = images_.back();
  if (rows.width != p.image.width || y0 < 0 || y0 + rows.height > p.image.height) return;
  std::copy(rows.rgb.begin(), rows.rgb.end(), p.image.rgb.begin() + static_cast<std::ptrdiff_t>(y0) * p.image.width * 3);
  if (p.dirtyFrom == p.dirtyTo) {
    p.dirtyFrom = y0, p.dirtyTo = y0 + rows.height;
  } else {
    p.dirtyFrom = std::min(p.dirtyFrom, y0), p.dirtyTo = std::max(p.dirtyTo, y0 + rows.height);
  }
  wake_.notify_all();
}

void TevDisplay::finish(double seconds) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!thread_.joinable()) return;
    finishing_ = true;
    if (!images_.empty()) images_.back().whole = true;
    wake_.notify_all();
  }
  // The thread sends what is left; a viewer that does not take it in time is cut off (the
  // thread's wait for room to send ends within kSendPollMs).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait_until(lock, deadline, [&] { return images_.empty() || broken_; });
    if (!images_.empty() && !broken_) {
      cancelled_ = true;   // a thread still connecting gives up once connected
      if (socket_.valid()) socket_.shutdownBoth();
      if (!warned_ && !quiet_)
        std::fprintf(stderr, "vkrt: warning: --display-server %s:%d: the viewer did not take the image in %.0f s; "
                             "the render is written all the same\n", address_.host.c_str(), address_.port, seconds);
      warned_ = true;
    }
  }
  thread_.join();
  socket_.close();
}

void TevDisplay::warn(const std::string& why) {
  std::lock_guard<std::mutex> lock(mutex_);
  broken_ = true;
  images_.clear();
  wake_.notify_all();
  if (warned_ || quiet_) return;
  warned_ = true;
  std::fprintf(stderr, "vkrt: warning: --display-server %s:%d: %s; the render goes on without it\n",
               address_.host.c_str(), address_.port, why.c_str());
}

void TevDisplay::run() {
  // Within kConnectSeconds: a host that never answers must not hold the end of the render.
  platform::SocketFailure failure;
  platform::Socket connected =
      platform::connectTcp(address_.host, address_.port, static_cast<int>(kConnectSeconds * 1000), failure);
  if (!connected.valid())
    return warn((failure.resolving ? "cannot find the host: " : "cannot connect: ") + failure.text);
  const platform::Socket* socket = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    socket_ = std::move(connected);
    socket = &socket_;   // (only finish() changes socket_, after this thread has ended)
    if (cancelled_) return;   // finish() gave up waiting while this connected
  }
  // Sends do not block: a viewer that takes nothing is waited for in polls of kSendPollMs, each
  // followed by a look at cancelled_. (A shutdown from finish()'s thread ends a send that
  // waits on Linux, but not on Windows, where it held the end of the render for good.)
  int error = 0;
  socket->setNonBlocking(true);
  auto sendAll = [&](const std::vector<std::uint8_t>& packet) {
    std::size_t at = 0;
    while (at < packet.size()) {
      const platform::Transfer sent = socket->send(packet.data() + at, packet.size() - at);
      if (sent.wouldBlock()) {
        if (cancelled_) return false;   // finish() has said why
        std::vector<platform::PollItem> room{{socket->native(), false, true}};
        if (platform::pollSockets(room, kSendPollMs, error) < 0) return false;
        continue;
      }
      if (sent.bytes <= 0) {
        error = sent.error;
        return false;
      }
      at += static_cast<std::size_t>(sent.bytes);
    }
    return true;
  };
  for (;;) {
    std::vector<std::vector<std::uint8_t>> packets;
    bool last = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] {
        if (broken_ || (finishing_ && images_.empty())) return true;
        if (images_.empty()) return false;
        const Pending& p = images_.front();
        return !p.created || p.dirtyFrom != p.dirtyTo || p.whole;
      });
      if (broken_ || images_.empty()) break;
      Pending& p = images_.front();
      if (!p.created) {
        packets.push_back(tevCreateImage(p.name, p.image.width, p.image.height));
        p.created = true;
      }
      if (p.whole) {
        for (auto& t : tevTiles(p.name, p.image, 0, p.image.height)) packets.push_back(std::move(t));
        images_.erase(images_.begin());
        last = finishing_ && images_.empty();
      } else if (p.dirtyFrom != p.dirtyTo) {
        for (auto& t : tevTiles(p.name, p.image, p.dirtyFrom, p.dirtyTo)) packets.push_back(std::move(t));
        p.dirtyFrom = p.dirtyTo = 0;
      }
    }
    for (const auto& packet : packets)
      if (!sendAll(packet)) return warn("the viewer closed the connection (" + platform::socketErrorText(error) + ")");
    if (last) {
      std::lock_guard<std::mutex> lock(mutex_);
      wake_.notify_all();
      break;
    }
  }
}

}  // namespace vkrt
