// vkrt view's server, apart from a browser (tests/cli/view_browser has the browser): the
// request head's parser and its limits, the server's bound on its connections, the view's
// routes and token, the state it sends as the watch steps, and the command line of `vkrt view`.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "net/http_request.h"
#include "net/http_server.h"
#include "platform/socket.h"
#include "cli/web_view.h"
#include "image/image_file.h"
#include "render/render.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

HeadParse parsed(const std::string& text) { return parseRequestHead(text); }

HttpRequest get(const std::string& target) {
  HeadParse p = parsed("GET " + target + " HTTP/1.1\r\nHost: h\r\n\r\n");
  EXPECT_EQ(p.kind, HeadParse::Complete) << target;
  return p.request;
}

}  // namespace

TEST(HttpRequest, ParsesTheRequestLineAndTheQuery) {
  HttpRequest r = get("/image.png?t=abc&v=3");
  EXPECT_EQ(r.method, "GET");
  EXPECT_EQ(r.path, "/image.png");
  EXPECT_EQ(r.query["t"], "abc");
  EXPECT_EQ(r.query["v"], "3");
  r = get("/a%20b?x=1+2&y=%41&empty=&flag&x=last");
  EXPECT_EQ(r.path, "/a b");
  EXPECT_EQ(r.query["x"], "last");   // a later repeat wins
  EXPECT_EQ(r.query["y"], "A");
  EXPECT_EQ(r.query["empty"], "");
  EXPECT_EQ(r.query.count("flag"), 1u);
  EXPECT_EQ(get("/a+b").path, "/a+b");   // '+' is a space only in the query
  // HTTP/1.0 and a bare-newline head are read too.
  EXPECT_EQ(parsed("GET / HTTP/1.0\n\n").kind, HeadParse::Complete);
}

TEST(HttpRequest, WaitsForTheWholeHead) {
  EXPECT_EQ(parsed("").kind, HeadParse::Incomplete);
  EXPECT_EQ(parsed("GET / HTTP/1.1\r\nHost: h\r\n").kind, HeadParse::Incomplete);
  EXPECT_EQ(parsed("GET / HTTP/1.1\r\nHost: h\r\n\r").kind, HeadParse::Incomplete);
}

TEST(HttpRequest, RefusesWhatIsMalformedOrTooLarge) {
  const std::pair<std::string, int> cases[] = {
      {"garbage\r\n\r\n", 400},
      {"GET  / HTTP/1.1\r\n\r\n", 400},
      {"GET / HTTP/1.1 x\r\n\r\n", 400},
      {"get / HTTP/1.1\r\n\r\n", 400},
      {"GET image.png HTTP/1.1\r\n\r\n", 400},
      {"GET http://h/ HTTP/1.1\r\n\r\n", 400},
      {"GET /%zz HTTP/1.1\r\n\r\n", 400},
      {"GET /a%2 HTTP/1.1\r\n\r\n", 400},
      {"GET /?t=%00 HTTP/1.1\r\n\r\n", 400},
      {"GET /\x7f HTTP/1.1\r\n\r\n", 400},
      {"GET / HTTP/2.0\r\n\r\n", 505},
      {"GET / SPDY\r\n\r\n", 505},
  };
  for (const auto& [text, status] : cases) {
    HeadParse p = parsed(text);
    EXPECT_EQ(p.kind, HeadParse::Refused) << text;
    EXPECT_EQ(p.status, status) << text;
    EXPECT_FALSE(p.reason.empty()) << text;
  }
  // Limits: a request line past kMaxRequestLine is refused before its end arrives; a head
  // past kMaxRequestHead too; one just under both is read.
  EXPECT_EQ(parsed("GET /" + std::string(kMaxRequestLine, 'a')).status, 414);
  EXPECT_EQ(parsed("GET /" + std::string(kMaxRequestLine - 20, 'a') + " HTTP/1.1\r\n\r\n").kind,
            HeadParse::Complete);
  const std::string line = "GET / HTTP/1.1\r\n";
  EXPECT_EQ(parsed(line + "X: " + std::string(kMaxRequestHead, 'b')).status, 431);
  EXPECT_EQ(parsed(line + "X: " + std::string(kMaxRequestHead, 'b') + "\r\n\r\n").status, 431);
  EXPECT_EQ(parsed(line + "X: " + std::string(kMaxRequestHead - 100, 'b') + "\r\n\r\n").kind, HeadParse::Complete);
}

namespace {

// A site that answers every request "ok".
class OkSite : public HttpSite {
 public:
  HttpResponse respond(const HttpRequest&) override {
    HttpResponse r;
    r.body = "ok";
    return r;
  }
  std::string nextEvent(std::uint64_t&) override { return ""; }
};

platform::Socket connectTo(int port) {
  platform::SocketFailure failure;
  platform::Socket s = platform::connectTcp("127.0.0.1", port, 2000, failure);
  EXPECT_TRUE(s.valid()) << failure.text;
  return s;
}

// What the server sends on `s` until it closes the connection, or `ms` of quiet.
std::string received(const platform::Socket& s, int ms) {
  std::string got;
  for (;;) {
    std::vector<platform::PollItem> items(1);
    items[0].handle = s.native(), items[0].wantRead = true;
    int error = 0;
    if (platform::pollSockets(items, ms, error) != 1) return got;
    char buffer[1024];
    const platform::Transfer t = s.receive(buffer, sizeof buffer);
    if (t.bytes <= 0) return got;
    got.append(buffer, static_cast<std::size_t>(t.bytes));
  }
}

}  // namespace

// Every place taken by a connection that has sent nothing: the next one takes the place of the
// OLDEST of them (which is sent 503), so that idle connections cannot keep the page from its
// browser; the newest idle ones keep theirs.
TEST(HttpServer, AFullServerGivesTheOldestIdleConnectionsPlaceToANewOne) {
  OkSite site;
  HttpServer server("127.0.0.1", 0, site);
  std::vector<platform::Socket> idle;
  for (int i = 0; i < kMaxConnections; ++i) {
    idle.push_back(connectTo(server.port()));
    // Accepted one by one, each at a later time than the one before.
    std::this_thread::sleep_for(std::chrono::milliseconds(i == 0 ? 50 : 10));
  }
  platform::Socket newest = connectTo(server.port());
  const std::string oldest = received(idle.front(), 2000);
  EXPECT_EQ(oldest.rfind("HTTP/1.1 503 Service Unavailable\r\n", 0), 0u) << oldest;
  EXPECT_NE(oldest.find("too many connections"), std::string::npos) << oldest;
  EXPECT_EQ(received(idle.back(), 200), "") << "the newest idle connection lost its place";
  EXPECT_EQ(received(idle[1], 200), "") << "only the oldest loses its place";
  // The new connection has its place: it is answered.
  const std::string request = "GET / HTTP/1.1\r\nHost: h\r\n\r\n";
  ASSERT_EQ(newest.send(request.data(), request.size()).bytes, static_cast<std::ptrdiff_t>(request.size()));
  const std::string answer = received(newest, 2000);
  EXPECT_EQ(answer.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << answer;
}

TEST(WebView, TheTokenGuardsEveryAddressAndNoFileIsServed) {
  const std::string token = randomToken();
  ASSERT_EQ(token.size(), 32u);
  EXPECT_NE(token, randomToken());
  WebView view("scene.test", token, std::nullopt);
  for (const char* path : {"/", "/events", "/image.png", "/nothing"}) {
    EXPECT_EQ(view.respond(get(std::string(path))).status, 403) << path;
    EXPECT_EQ(view.respond(get(std::string(path) + "?t=" + token.substr(1))).status, 403) << path;
    EXPECT_EQ(view.respond(get(std::string(path) + "?t=" + token + "0")).status, 403) << path;
  }
  const std::string t = "?t=" + token;
  HttpResponse page = view.respond(get("/" + t));
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.contentType, "text/html; charset=utf-8");
  EXPECT_TRUE(contains(page.extraHeaders, "Content-Security-Policy: default-src 'none'"));
  EXPECT_TRUE(contains(page.body, "new EventSource(\"events?t=\""));
  EXPECT_FALSE(contains(page.body, "http://") && contains(page.body, "<script src"));   // nothing fetched from elsewhere
  EXPECT_EQ(view.respond(get("/image.png" + t)).status, 404);   // no image yet
  for (const char* path : {"/scene.test", "/etc/passwd", "/../scene.test", "/index.html", "/favicon.ico"})
    EXPECT_EQ(view.respond(get(std::string(path) + t)).status, 404) << path;
  HttpResponse events = view.respond(get("/events" + t));
  EXPECT_TRUE(events.stream);
  EXPECT_EQ(events.contentType, "text/event-stream");
}

TEST(WebView, TheStateFollowsTheWatchAndTheImageIsAPng) {
  const std::string token = randomToken();
  WebView view("a \"quoted\"\nscene.test", token, std::nullopt);
  int notified = 0;
  view.onChange([&notified] { ++notified; });
  std::uint64_t seen = 0;
  std::string event = view.nextEvent(seen);
  EXPECT_TRUE(contains(event, "\"phase\":\"starting\"")) << event;
  EXPECT_TRUE(contains(event, "\"scene\":\"a \\\"quoted\\\"\\u000ascene.test\"")) << event;   // one JSON line
  EXPECT_EQ(event.find('\n'), event.size() - 2);
  EXPECT_EQ(view.nextEvent(seen), "");   // nothing newer

  view.roundStarted(1);
  RenderReport report;
  report.outputPath = "out.png";
  report.width = 4, report.height = 2, report.gamma = 1.0;
  view.imageStart(report);
  RadianceImage band(4, 1);
  for (float& c : band.rgb) c = 1.0f;
  view.imageRows(1, band);   // the lower row, white
  view.imageRows(5, band);   // outside the image: ignored
  view.warned("scene.test:3: warning: unknown command 'x'");
  EXPECT_GE(notified, 4);
  event = view.nextEvent(seen);
  EXPECT_TRUE(contains(event, "\"phase\":\"rendering\"")) << event;
  EXPECT_TRUE(contains(event, "\"rows\":2")) << event;
  EXPECT_TRUE(contains(event, "\"warnings\":[\"scene.test:3: warning: unknown command 'x'\"]")) << event;

  HttpResponse png = view.respond(get("/image.png?t=" + token));
  ASSERT_EQ(png.status, 200);
  EXPECT_EQ(png.contentType, "image/png");
  const std::string path = freshDir("cli/web-view") + "/served.png";
  ASSERT_TRUE(png.sharedBody);   // one copy for every connection that asks
  writeFile(path, *png.sharedBody);
  Image served = readImage(path);
  ASSERT_EQ(served.width, 4);
  ASSERT_EQ(served.height, 2);
  EXPECT_EQ(served.pixel(0, 0)[0], 0);
  EXPECT_EQ(served.pixel(3, 1)[2], 255);

  view.rendered({1, 1, 1, 1, 0.25, "out.png", "vkrt: watch: [1] wrote out.png (4x2) in 0.250 s\n"});
  event = view.nextEvent(seen);
  EXPECT_TRUE(contains(event, "\"phase\":\"done\"")) << event;
  EXPECT_TRUE(contains(event, "\"line\":\"vkrt: watch: [1] wrote out.png (4x2) in 0.250 s\"")) << event;
  EXPECT_TRUE(contains(event, "\"check\":null")) << event;

  view.roundStarted(2);
  view.failed(2, "scene.test:6: error: 'sphere' expects 4 arguments\n");
  event = view.nextEvent(seen);
  EXPECT_TRUE(contains(event, "\"phase\":\"failed\"")) << event;
  EXPECT_TRUE(contains(event, "\"error\":\"scene.test:6: error: 'sphere' expects 4 arguments\\u000a\"")) << event;
  EXPECT_TRUE(contains(event, "\"warnings\":[]")) << event;   // a round's warnings are its own
  EXPECT_EQ(*view.respond(get("/image.png?t=" + token)).sharedBody, *png.sharedBody);   // the last image stays
}

TEST(WebView, WithAReferenceEachImageIsAPointOfThePlot) {
  Image reference(2, 1);
  reference.pixel(0, 0)[0] = 10;   // the rest 0
  WebView view("s.test", randomToken(), ViewReference{"ref.png", reference});
  view.roundStarted(1);
  RenderReport report;
  report.width = 2, report.height = 1;
  view.imageStart(report);
  view.imageRows(0, RadianceImage(2, 1));   // black
  view.rendered({1, 1, 64, 1, 0.5, "o.png", ""});
  std::uint64_t seen = 0;
  std::string event = view.nextEvent(seen);
  // One channel of six differs by 10: RMSE sqrt(100 / 6).
  EXPECT_TRUE(contains(event, "\"points\":[[0.5,4.08248]]")) << event;
  EXPECT_TRUE(contains(event, "\"reference\":\"ref.png\"")) << event;
  EXPECT_TRUE(contains(event, "largest difference 10/255, 1 of 2 pixels differ")) << event;
  report.width = 3;
  view.imageStart(report);
  view.rendered({1, 2, 64, 2, 0.7, "o.png", ""});
  event = view.nextEvent(seen);
  EXPECT_TRUE(contains(event, "the reference is 2x1, the render 3x1: not compared")) << event;
  EXPECT_TRUE(contains(event, "\"points\":[[0.5,4.08248]]")) << event;   // no point for it
}

TEST(ViewCommand, OptionsThatDoNotGoWithItAreUsageErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"view", "view takes one scene"},
      {"view a.test b.test", "view takes one scene: vkrt view [options] SCENE.test (got 2)"},
      {"view --compare a.test", "--compare does not go with it"},
      {"view --watch a.test", "--watch (view watches the scene already) does not go with it"},
      {"view --time 3 a.test", "--time does not go with it"},
      {"view --dry-run a.test", "--dry-run does not go with it"},
      {"view --json a.test", "--json does not go with it"},
      {"view --max-diff 3 a.test", "a threshold (--max-...) does not go with it"},
      {"view --port 0 a.test", "--port"},
      {"view --port 70000 a.test", "--port"},
      {"view --bind= a.test", "option --bind needs an address"},
      {"--port 8080 a.test", "--bind and --port go with vkrt view"},
      {"--bind 0.0.0.0 a.test", "--bind and --port go with vkrt view"},
      {"veiw a.test", "did you mean 'view'?"},
  };
  for (const auto& [args, message] : cases) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
  // An address that is not this machine's: an I/O error, before anything renders.
  const std::string dir = freshDir("cli/view-command");
  writeFile(dir + "/a.test", "size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\n");
  RunResult r = runVkrt("view --bind 192.0.2.1 " + dir + "/a.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("cannot listen on 192.0.2.1 port 0"), std::string::npos) << r.output;
  EXPECT_FALSE(fileExists(dir + "/a.png"));
  // An output that cannot be written: an error before any address is printed (a script that
  // waits for the first line is not handed one that never answers).
  RunResult out = runCommand("'" + vkrtBinary() + "' view -o " + dir + "/no/such/folder/a.png " + dir +
                             "/a.test 2>/dev/null");
  EXPECT_EQ(out.exitCode, 4) << out.output;
  EXPECT_EQ(out.output, "") << "nothing on stdout";
}
