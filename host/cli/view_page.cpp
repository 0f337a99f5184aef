// The page of `vkrt view`: view_page.h. Element ids the script and the tests read: image
// (data-version: the image shown), phase, round, samples, seconds, progress, warnings, error,
// check, plot, connection.
#include "cli/view_page.h"

namespace vkrt {

std::string_view viewPage() {
  return R"page(<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>vkrt view</title>
<link rel="icon" href="data:image/svg+xml,%3Csvg xmlns=%22http://www.w3.org/2000/svg%22 viewBox=%220 0 16 16%22%3E%3Ccircle cx=%228%22 cy=%228%22 r=%226%22 fill=%22%236cb6ff%22/%3E%3C/svg%3E">
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 0; background: #1d1f21; color: #e0e0e0; }
header { display: flex; gap: 1em; align-items: baseline; padding: 0.6em 1em; background: #2a2d30; }
h1 { font-size: 1.1em; margin: 0; font-weight: 600; }
h2 { font-size: 1em; margin: 1em 0 0.3em; }
.phase { padding: 0.1em 0.6em; border-radius: 0.8em; background: #444; }
.phase.done { background: #2e6b3a; } .phase.failed { background: #8b2b2b; }
.phase.rendering, .phase.refining { background: #6b5a1e; }
main { display: flex; flex-wrap: wrap; gap: 1.5em; padding: 1em; align-items: flex-start; }
figure { margin: 0; }
#frame { background: repeating-conic-gradient(#333 0 25%, #2a2a2a 0 50%) 0 0 / 16px 16px; min-width: 64px; min-height: 64px; }
#frame img { display: block; max-width: calc(100vw - 2em); image-rendering: pixelated; }
figcaption { color: #aaa; margin-top: 0.4em; font-family: ui-monospace, monospace; font-size: 12px; }
section { min-width: 18em; max-width: 48em; flex: 1; }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 0.2em 1em; margin: 0.6em 0; }
dt { color: #aaa; } dd { margin: 0; font-variant-numeric: tabular-nums; }
progress { width: 100%; }
pre { white-space: pre-wrap; font-size: 12px; padding: 0.6em; border-radius: 4px; }
#error { background: #3b1e1e; color: #ffb4b4; }
#warnings { padding-left: 1.2em; color: #f0d58c; font-family: ui-monospace, monospace; font-size: 12px; }
svg { background: #25282b; border-radius: 4px; }
svg text { fill: #aaa; font-size: 11px; }
#connection { color: #f08c8c; }
</style>
</head>
<body data-round="0" data-phase="connecting">
<header><h1 id="scene">vkrt view</h1><span id="phase" class="phase">connecting</span></header>
<main>
<figure><div id="frame"><img id="image" alt="" data-version="0"></div><figcaption id="line"></figcaption></figure>
<section>
<progress id="progress" max="1" value="0"></progress>
<dl>
<dt>round</dt><dd id="round">-</dd>
<dt>samples per pixel</dt><dd id="samples">-</dd>
<dt>time</dt><dd id="seconds">-</dd>
<dt>image</dt><dd id="output">-</dd>
</dl>
<pre id="error" hidden></pre>
<ul id="warnings"></ul>
<div id="check" hidden>
<h2>error against time (RMSE in 8-bit steps against <span id="reference"></span>)</h2>
<svg id="plot" width="420" height="200" viewBox="0 0 420 200" role="img"></svg>
<p id="checknote"></p>
</div>
<p id="connection"></p>
</section>
</main>
<script>
"use strict";
const token = new URLSearchParams(location.search).get("t") || "";
const $ = (id) => document.getElementById(id);
let wanted = 0, shown = 0, loading = false;

// The newest image, loaded beside the one shown and swapped in whole once it has arrived.
function loadImage() {
  if (loading || wanted === 0 || wanted === shown) return;
  loading = true;
  const version = wanted, next = new Image();
  next.onload = () => {
    next.id = "image";
    next.alt = "the render";
    next.dataset.version = String(version);
    // A small image is shown larger, by a whole factor (its pixels kept sharp).
    const factor = Math.max(1, Math.floor(256 / Math.max(next.naturalWidth, next.naturalHeight)));
    if (factor > 1) next.style.width = next.naturalWidth * factor + "px";
    $("image").replaceWith(next);
    shown = version;
    loading = false;
    loadImage();
  };
  next.onerror = () => { loading = false; setTimeout(loadImage, 500); };
  next.src = "image.png?t=" + encodeURIComponent(token) + "&v=" + version;
}

function fixed(x, digits) { return Number(x).toFixed(digits); }

function plot(points) {
  const svg = $("plot"), w = 420, h = 200, left = 44, bottom = 24;
  while (svg.firstChild) svg.removeChild(svg.firstChild);
  const ns = "http://www.w3.org/2000/svg";
  const add = (name, attributes, text) => {
    const e = document.createElementNS(ns, name);
    for (const k in attributes) e.setAttribute(k, attributes[k]);
    if (text !== undefined) e.textContent = text;
    svg.appendChild(e);
    return e;
  };
  add("line", { x1: left, y1: h - bottom, x2: w - 8, y2: h - bottom, stroke: "#666" });
  add("line", { x1: left, y1: 8, x2: left, y2: h - bottom, stroke: "#666" });
  if (points.length === 0) return;
  const tMax = Math.max(...points.map((p) => p[0]), 1e-3), eMax = Math.max(...points.map((p) => p[1]), 1e-3);
  const x = (t) => left + (t / tMax) * (w - left - 8), y = (e) => h - bottom - (e / eMax) * (h - bottom - 8);
  add("text", { x: 2, y: 14 }, fixed(eMax, 2));
  add("text", { x: 2, y: h - bottom }, "0");
  add("text", { x: w - 60, y: h - 6 }, fixed(tMax, 2) + " s");
  add("polyline", { points: points.map((p) => x(p[0]) + "," + y(p[1])).join(" "), fill: "none", stroke: "#6cb6ff",
                    "stroke-width": 2 });
  for (const p of points) add("circle", { cx: x(p[0]), cy: y(p[1]), r: 3, fill: "#6cb6ff" });
}

function show(s) {
  document.title = s.scene + " - " + s.phase + " - vkrt view";
  document.body.dataset.round = String(s.round);
  document.body.dataset.phase = s.phase;
  $("scene").textContent = s.scene;
  $("phase").textContent = s.phase;
  $("phase").className = "phase " + s.phase;
  $("round").textContent = s.round ? String(s.round) : "-";
  $("samples").textContent = s.samples ? String(s.samples) + (s.path ? " (batch " + s.batch + " of " + s.batches + ")" : "") : "-";
  $("seconds").textContent = s.phase === "done" || s.phase === "refining" ? fixed(s.seconds, 3) + " s" : "-";
  $("output").textContent = s.output ? s.output + " (" + s.width + "x" + s.height + ")" : "-";
  $("line").textContent = s.line;
  const progress = s.phase === "done" ? 1 : s.path ? (s.batches ? s.batch / s.batches : 0) : (s.height ? s.rows / s.height : 0);
  $("progress").value = progress;
  $("error").hidden = !s.error;
  $("error").textContent = s.error;
  const list = $("warnings");
  while (list.firstChild) list.removeChild(list.firstChild);
  for (const w of s.warnings) {
    const li = document.createElement("li");
    li.textContent = w;
    list.appendChild(li);
  }
  $("check").hidden = !s.check;
  if (s.check) {
    $("reference").textContent = s.check.reference;
    $("checknote").textContent = s.check.note;
    plot(s.check.points);
  }
  wanted = s.image;
  loadImage();
}

const events = new EventSource("events?t=" + encodeURIComponent(token));
events.onmessage = (m) => { $("connection").textContent = ""; show(JSON.parse(m.data)); };
events.onerror = () => { $("connection").textContent = "lost the connection to vkrt; trying again"; };
</script>
</body>
</html>
)page";
}

}  // namespace vkrt
