// --display-server HOST:PORT (pbrt-v4's name and meaning): the render shown in tev or HDRView
// as it refines, over tev's network protocol (its IPC packets, as the tevclient package
// writes them): an image created once per render, named for its output file, and updated
// with linear RGB tiles of at most 128x128 as bands and batches finish, then whole at the end.
//
// The render never waits for the viewer: update() copies the rows into the display's own
// image and returns; a thread of its own connects and sends, taking whatever rows changed
// since it last sent (so a slow viewer sees fewer, larger updates). A viewer that is not
// there, or that goes away, costs one warning (on stderr, unless quiet) and nothing else.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "image/radiance_image.h"
#include "platform/socket.h"

namespace vkrt {

// HOST:PORT (a name or an IPv4 address, [v6] in brackets; PORT 1-65535): throws UsageError.
struct DisplayAddress {
  std::string host;
  int port = 0;
};
DisplayAddress parseDisplayAddress(const std::string& text);

// The packets tev's protocol sends (each: uint32 length of the whole packet, uint8 type,
// then its fields, little-endian; strings NUL-terminated).
std::vector<std::uint8_t> tevCreateImage(const std::string& name, int width, int height);
// Rows [y0, y0 + rows) x columns [x0, x0 + width) of `image`, channels R, G, B.
std::vector<std::uint8_t> tevUpdateImage(const std::string& name, const RadianceImage& image, int x0, int y0, int width,
                                         int rows);
// Every 128x128 tile (tevclient's tiling: rows of tiles from the top left) of `image` that
// meets rows [y0, y1): the packets, in that order.
std::vector<std::vector<std::uint8_t>> tevTiles(const std::string& name, const RadianceImage& image, int y0, int y1);

class TevDisplay {
 public:
  TevDisplay(DisplayAddress address, bool quiet);
  ~TevDisplay();   // finish()es
  TevDisplay(const TevDisplay&) = delete;
  TevDisplay& operator=(const TevDisplay&) = delete;

  // A new image (a render's): created in the viewer, shown black until updated.
  void begin(const std::string& name, int width, int height);
  // Rows of the current image are finished (or refined): `rows` holds rows y0.. of it.
  void update(int y0, const RadianceImage& rows);
  // Sends what is left, the whole current image last, waiting for the viewer at most
  // `seconds`; then closes the connection.
  void finish(double seconds = 2.0);

 private:
  void run();
  void warn(const std::string& why);

  DisplayAddress address_;
  bool quiet_;
  std::mutex mutex_;
  std::condition_variable wake_;
  // What the thread is to send (under mutex_): the images begun, each with its rows changed.
  struct Pending {
    std::string name;
    RadianceImage image;
    bool created = false;
    int dirtyFrom = 0, dirtyTo = 0;   // rows changed and not sent: [from, to)
    bool whole = false;               // the last: every tile, once
  };
  std::vector<Pending> images_;
  bool finishing_ = false, broken_ = false, warned_ = false;
  std::atomic<bool> cancelled_{false};   // finish() gave up: the thread stops connecting or sending
  platform::Socket socket_;   // connected (by the thread)
  std::thread thread_;
};

}  // namespace vkrt
