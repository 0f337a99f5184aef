// vkrt view: view_scene.h.
#include "cli/view_scene.h"

#include <cstdio>
#include <optional>

#include "cli/watch.h"
#include "cli/web_view.h"
#include "image/image_file.h"
#include "net/http_server.h"
#include "platform/socket.h"

namespace vkrt {

int viewScene(RenderOptions& options) {
  checkWatchOutputs(options);   // before the address is printed: a script would wait on it
  RenderOptions o = options;    // its hooks lead to the view, which ends with this function
  std::optional<ViewReference> reference;
  if (o.checkAgainst) reference = ViewReference{*o.checkAgainst, readImage(*o.checkAgainst)};
  WebView view(o.request.scenePath, randomToken(), std::move(reference));
  HttpServer server(o.bind, o.port, view);   // (stopped before the view goes)
  view.onChange([&server] { server.notify(); });
  // The image goes to the page beside any other viewer (--display-server).
  o.request.onImageStart = [&view, other = o.request.onImageStart](const RenderReport& report) {
    if (other) other(report);
    view.imageStart(report);
  };
  o.request.onImageRows = [&view, other = o.request.onImageRows](int y0, const RadianceImage& rows) {
    if (other) other(y0, rows);
    view.imageRows(y0, rows);
  };
  // Listening on every address (--bind 0.0.0.0): the address others reach is the machine's name.
  std::string host = server.urlHost();
  if (host == "0.0.0.0" || host == "[::]") {
    if (std::string name = platform::hostName(); !name.empty()) host = name;
  }
  const std::string url = "http://" + host + ":" + std::to_string(server.port()) + "/?t=" + view.token();
  std::printf("%s\n", url.c_str());
  std::fflush(stdout);
  if (!o.quiet)
    std::fprintf(stderr,
                 "vkrt: view: open %s in a browser (from another machine: ssh -L %d:localhost:%d HOST, then the "
                 "same address); Ctrl-C ends\n",
                 url.c_str(), server.port(), server.port());
  return watchScene(o, &view);
}

}  // namespace vkrt
