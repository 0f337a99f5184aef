// What `vkrt view`'s page shows, and the site that serves it (net/http_server.h): the watch
// loop's steps (cli/watch.h: rounds, warnings and errors with their lines, each image written
// or refined) and the render's rows as they come, held here under one lock; the server's
// thread reads them. Three addresses, each only with the token (a random 128-bit number, in
// the URL vkrt prints): `/` the page (cli/view_page.h), `/events` its event stream (the state
// as JSON, sent as it changes), `/image.png` the latest image (encoded when first asked for).
// Anything else: 404; no token, or a wrong one: 403. Nothing of the file system is served.
//
// With a reference (--check REF), each image written is compared with it: its RMSE in 8-bit
// steps, against the seconds since the round's change, is the page's plot.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "net/http_server.h"
#include "cli/watch.h"
#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// A random token: 32 hex digits from the system's random source (platform/random.h). Throws IoError.
std::string randomToken();

struct ViewReference {
  std::string path;
  Image image;
};

class WebView : public HttpSite, public WatchListener {
 public:
  WebView(std::string scenePath, std::string token, std::optional<ViewReference> reference);

  const std::string& token() const { return token_; }

  // Called when the state changes (the server's notify): set before the watch starts.
  void onChange(std::function<void()> notify) { notify_ = std::move(notify); }

  // The render's image (RenderRequest's onImageStart and onImageRows).
  void imageStart(const RenderReport& report);
  void imageRows(int y0, const RadianceImage& rows);

  // WatchListener
  void roundStarted(int round) override;
  void warned(const std::string& line) override;
  void rendered(const WatchStep& step) override;
  void failed(int round, const std::string& message) override;

  // HttpSite
  HttpResponse respond(const HttpRequest& request) override;
  std::string nextEvent(std::uint64_t& seen) override;

  // The state as the page receives it (one JSON object).
  std::string stateJson();

 private:
  std::string stateJsonLocked() const;
  void changed();   // under mutex_: the state's version moves on (the caller notifies)
  void notify() {
    if (notify_) notify_();
  }
  HttpResponse image();

  const std::string scenePath_, token_;
  const std::optional<ViewReference> reference_;
  std::function<void()> notify_;

  std::mutex mutex_;
  std::uint64_t version_ = 1;
  int round_ = 0;
  std::string phase_ = "starting";   // rendering, refining, done, failed
  std::string output_, line_;
  std::vector<std::string> warnings_;
  std::string error_;                // the failed round's message; the image stays the last one
  double gamma_ = 1.0;
  bool pathIntegrator_ = false;
  int rowsDone_ = 0;                 // of the image's height, this round's first render
  int batch_ = 0, batches_ = 0;
  std::uint64_t samples_ = 0;
  double seconds_ = 0;
  RadianceImage image_;              // the latest rows, linear
  std::uint64_t imageVersion_ = 0;   // 0: no image yet
  std::shared_ptr<const std::string> png_;   // image_ encoded, at pngVersion_ (shared by its responses)
  std::uint64_t pngVersion_ = 0;
  std::vector<std::pair<double, double>> checkPoints_;   // (seconds, RMSE), this round
  std::string checkNote_;            // the latest comparison, in words
};

}  // namespace vkrt
