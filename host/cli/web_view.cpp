// `vkrt view`'s state and routes: web_view.h.
#include "cli/web_view.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "cli/view_page.h"
#include "compare/image_diff.h"
#include "image/encode.h"
#include "image/png.h"
#include "platform/random.h"
#include "render/render.h"
#include "util/errors.h"
#include "util/json.h"

namespace vkrt {
namespace {

constexpr std::size_t kMaxWarningsShown = 200;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string withoutNewline(std::string line) {
  while (!line.empty() && line.back() == '\n') line.pop_back();
  return line;
}

// Whether `given` is the token, in time that does not depend on where they differ.
bool sameToken(const std::string& given, const std::string& token) {
  unsigned char differ = given.size() != token.size();
  for (std::size_t i = 0; i < token.size(); ++i) differ |= static_cast<unsigned char>(i < given.size() ? given[i] ^ token[i] : 1);
  return differ == 0;
}

HttpResponse text(int status, const std::string& body) {
  HttpResponse r;
  r.status = status;
  r.body = body + "\n";
  return r;
}

}  // namespace

std::string randomToken() {
  unsigned char bytes[16];
  try {
    platform::randomBytes(bytes, sizeof bytes);
  } catch (const std::runtime_error& e) {
    throw IoError(std::string("cannot make the page's token: ") + e.what());
  }
  std::string token;
  for (unsigned char b : bytes) {
    static constexpr char kHex[] = "0123456789abcdef";
    token += kHex[b >> 4];
    token += kHex[b & 15];
  }
  return token;
}

WebView::WebView(std::string scenePath, std::string token, std::optional<ViewReference> reference)
    : scenePath_(std::move(scenePath)), token_(std::move(token)), reference_(std::move(reference)) {}

void WebView::changed() { ++version_; }

void WebView::imageStart(const RenderReport& report) {
  {
    std::lock_guard lock(mutex_);
    output_ = report.outputPath;
    gamma_ = report.gamma;
    pathIntegrator_ = report.pathIntegrator;
    rowsDone_ = 0;
    // The last image stays until the new one's rows cover it (a new size: black until then).
    if (image_.width != report.width || image_.height != report.height)
      image_ = RadianceImage(report.width, report.height);
    changed();
  }
  notify();
}

void WebView::imageRows(int y0, const RadianceImage& rows) {
  {
    std::lock_guard lock(mutex_);
    if (rows.width != image_.width || y0 < 0 || y0 + rows.height > image_.height) return;
    std::copy(rows.rgb.begin(), rows.rgb.end(), image_.rgb.begin() + static_cast<std::ptrdiff_t>(y0) * image_.width * 3);
    image_.samples = rows.samples;
    rowsDone_ = std::max(rowsDone_, y0 + rows.height);
    imageVersion_ = version_ + 1;
    changed();
  }
  notify();
}

void WebView::roundStarted(int round) {
  {
    std::lock_guard lock(mutex_);
    round_ = round;
    phase_ = "rendering";
    warnings_.clear();
    error_.clear();
    line_.clear();
    checkPoints_.clear();
    checkNote_.clear();
    batch_ = batches_ = 0;
    samples_ = 0;
    seconds_ = 0;
    changed();
  }
  notify();
}

void WebView::warned(const std::string& line) {
  {
    std::lock_guard lock(mutex_);
    if (warnings_.size() < kMaxWarningsShown) warnings_.push_back(withoutNewline(line));
    changed();
  }
  notify();
}

void WebView::rendered(const WatchStep& step) {
  RadianceImage image;
  double gamma = 1;
  {
    std::lock_guard lock(mutex_);
    phase_ = step.batch < step.batches ? "refining" : "done";
    batch_ = step.batch, batches_ = step.batches;
    samples_ = step.samples;
    seconds_ = step.seconds;
    output_ = step.output;
    line_ = withoutNewline(step.line);
    if (reference_) image = image_, gamma = gamma_;
  }
  if (reference_) {   // compared outside the lock: the page is served meanwhile
    const Image& ref = reference_->image;
    std::string note;
    std::optional<double> rmse;
    if (ref.width != image.width || ref.height != image.height) {
      note = "the reference is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + ", the render " +
             std::to_string(image.width) + "x" + std::to_string(image.height) + ": not compared";
    } else {
      const ImageDiff diff = compare(encodeImage(image, gamma), ref);
      rmse = diff.rmse;
      note = "RMSE " + number(diff.rmse) + ", largest difference " + std::to_string(diff.maxChannelDiff) + "/255, " +
             std::to_string(diff.differing.size()) + " of " + std::to_string(diff.pixels) + " pixels differ";
    }
    std::lock_guard lock(mutex_);
    if (rmse) checkPoints_.emplace_back(step.seconds, *rmse);
    checkNote_ = note;
  }
  {
    std::lock_guard lock(mutex_);
    changed();
  }
  notify();
}

void WebView::failed(int round, const std::string& message) {
  {
    std::lock_guard lock(mutex_);
    round_ = round;
    phase_ = "failed";
    error_ = message;
    changed();
  }
  notify();
}

std::string WebView::stateJson() {
  std::lock_guard lock(mutex_);
  return stateJsonLocked();
}

std::string WebView::stateJsonLocked() const {
  std::string warnings;
  for (const std::string& w : warnings_) warnings += (warnings.empty() ? "" : ",") + jsonQuoted(w);
  std::string check = "null";
  if (reference_) {
    std::string points;
    for (const auto& [t, e] : checkPoints_) points += (points.empty() ? "[" : ",[") + number(t) + "," + number(e) + "]";
    check = "{\"reference\":" + jsonQuoted(reference_->path) + ",\"points\":[" + points +
            "],\"note\":" + jsonQuoted(checkNote_) + "}";
  }
  return "{\"version\":" + std::to_string(version_) + ",\"scene\":" + jsonQuoted(scenePath_) +
         ",\"round\":" + std::to_string(round_) + ",\"phase\":" + jsonQuoted(phase_) +
         ",\"output\":" + jsonQuoted(output_) + ",\"line\":" + jsonQuoted(line_) + ",\"warnings\":[" + warnings +
         "],\"error\":" + jsonQuoted(error_) + ",\"path\":" + (pathIntegrator_ ? "true" : "false") +
         ",\"width\":" + std::to_string(image_.width) + ",\"height\":" + std::to_string(image_.height) +
         ",\"rows\":" + std::to_string(rowsDone_) + ",\"batch\":" + std::to_string(batch_) +
         ",\"batches\":" + std::to_string(batches_) + ",\"samples\":" + std::to_string(samples_) +
         ",\"seconds\":" + number(seconds_) + ",\"image\":" + std::to_string(imageVersion_) + ",\"check\":" + check + "}";
}

std::string WebView::nextEvent(std::uint64_t& seen) {
  std::lock_guard lock(mutex_);
  if (seen == version_) return "";
  seen = version_;
  return "data: " + stateJsonLocked() + "\n\n";
}

HttpResponse WebView::image() {
  RadianceImage copy;
  double gamma = 1;
  std::uint64_t version = 0;
  {
    std::lock_guard lock(mutex_);
    if (imageVersion_ == 0) return text(404, "404 Not Found: no image yet");
    if (pngVersion_ != imageVersion_) copy = image_, gamma = gamma_, version = imageVersion_;
  }
  if (version != 0) {   // encoded outside the lock: the render does not wait for it
    auto png = std::make_shared<const std::string>(pngBytes(copy, gamma));
    std::lock_guard lock(mutex_);
    png_ = std::move(png);
    pngVersion_ = version;
  }
  HttpResponse r;
  r.contentType = "image/png";
  std::lock_guard lock(mutex_);
  r.sharedBody = png_;
  return r;
}

HttpResponse WebView::respond(const HttpRequest& request) {
  const auto token = request.query.find("t");
  if (token == request.query.end() || !sameToken(token->second, token_))
    return text(403, "403 Forbidden: open the address vkrt view printed (it holds the page's token)");
  try {
    if (request.path == "/") {
      HttpResponse r;
      r.contentType = "text/html; charset=utf-8";
      r.body = std::string(viewPage());
      r.extraHeaders =
          "Content-Security-Policy: default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
          "img-src 'self' data:; connect-src 'self'\r\n";
      return r;
    }
    if (request.path == "/events") {
      HttpResponse r;
      r.contentType = "text/event-stream";
      r.stream = true;
      r.body = "retry: 1000\n\n";
      return r;
    }
    if (request.path == "/image.png") return image();
  } catch (const std::exception& e) {   // (an image that cannot be encoded now: Ctrl-C, memory)
    return text(503, std::string("503 Service Unavailable: ") + e.what());
  }
  return text(404, "404 Not Found");
}

}  // namespace vkrt
