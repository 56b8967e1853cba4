#include "run/ReplayReportPage.h"

namespace rmfx {

const char* replayReportStyle() {
    return R"CSS(
body { font: 14px/1.4 system-ui, sans-serif; margin: 0; background: #f4f4f4; color: #222; }
header { position: sticky; top: 0; z-index: 2; background: #222; color: #eee; padding: 8px 16px; }
header h1 { font-size: 18px; margin: 0 0 4px 0; }
header .summary { margin: 0 0 6px 0; }
header label { margin-right: 16px; }
main { padding: 8px 16px; }
.case { background: #fff; border-left: 6px solid #3a3; margin: 12px 0; padding: 8px 12px; }
.case.failed, .case.error { border-left-color: #d22; }
.case h2 { font-size: 16px; margin: 4px 0; }
.badge { display: inline-block; padding: 0 6px; border-radius: 3px; font-size: 12px; color: #fff; background: #3a3; }
.failed > h2 .badge, .error > h2 .badge, .compare.failed h3 .badge { background: #d22; }
.time { color: #777; font-weight: normal; font-size: 13px; }
pre.log { background: #f7f7f7; padding: 6px; overflow-x: auto; font-size: 12px; margin: 4px 0; }
.compare { border-top: 1px solid #ddd; padding: 6px 0; }
.compare h3 { font-size: 14px; margin: 4px 0; }
.first-difference { background: #fff4f4; padding: 4px 8px; }
table.metrics { border-collapse: collapse; margin: 4px 0; }
table.metrics td, table.metrics th { border: 1px solid #ddd; padding: 2px 8px; text-align: right; }
table.metrics td:first-child, table.metrics th:first-child { text-align: left; }
tr.over td { color: #c00; font-weight: bold; }
.problem { color: #c00; font-weight: bold; }
.view { display: none; gap: 12px; flex-wrap: wrap; align-items: flex-start; margin: 6px 0; }
.compare[data-view="side"] .view.side, .compare[data-view="slider"] .view.slider,
.compare[data-view="flicker"] .view.flicker { display: flex; }
figure { margin: 0; }
figcaption { font-size: 12px; color: #555; }
canvas, img.heat { image-rendering: pixelated; background: #888; display: block; }
.stack { position: relative; display: inline-block; }
.stack canvas.top { position: absolute; left: 0; top: 0; }
.flicker .stack canvas.top.hidden { visibility: hidden; }
.legend { display: flex; align-items: center; gap: 4px; font-size: 12px; }
.legend .bar { width: 120px; height: 10px; background: linear-gradient(to right, #000004, #1c1044, #4f127b,
  #812581, #b5367a, #e55064, #fb8761, #fec287, #fcfdbf); }
.legend .over { width: 10px; height: 10px; background: #00e5ff; }
.files a { margin-right: 12px; }
)CSS";
}

const char* replayReportScript() {
    return R"JS(
"use strict";
(function () {
  const images = window.rmfxImages || {};
  const decoded = {};  // id -> {w, h, rgb: Float32Array}
  const ev = document.getElementById("ev");
  const evValue = document.getElementById("ev-value");
  const op = document.getElementById("op");

  function srgb(x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055; }

  function decode(id) {
    return new Promise(function (resolve, reject) {
      const img = new Image();
      img.onload = function () {
        const w = img.naturalWidth, h = img.naturalHeight / 2;
        const c = document.createElement("canvas");
        c.width = w; c.height = 2 * h;
        const g = c.getContext("2d");
        g.drawImage(img, 0, 0);
        const bytes = g.getImageData(0, 0, w, 2 * h).data;
        const rgb = new Float32Array(w * h * 3);
        for (let i = 0; i < w * h; ++i) {
          const e = bytes[(w * h + i) * 4];
          const scale = e === 0 ? 0 : Math.pow(2, e - 136);
          for (let k = 0; k < 3; ++k) {
            const m = bytes[i * 4 + k];
            rgb[i * 3 + k] = m === 0 ? 0 : (m + 0.5) * scale;
          }
        }
        decoded[id] = { w: w, h: h, rgb: rgb };
        resolve();
      };
      img.onerror = function () { reject(new Error("cannot decode " + id)); };
      img.src = images[id];
    });
  }

  function paint(canvas) {
    const d = decoded[canvas.dataset.hdr];
    if (!d) { canvas.dataset.state = "missing"; return; }
    canvas.width = d.w; canvas.height = d.h;
    const g = canvas.getContext("2d");
    const out = g.createImageData(d.w, d.h);
    const gain = Math.pow(2, parseFloat(ev.value));
    const reinhard = op.value === "reinhard";
    let sum = 0;
    for (let i = 0; i < d.w * d.h; ++i) {
      for (let k = 0; k < 3; ++k) {
        let x = d.rgb[i * 3 + k] * gain;
        if (reinhard) x = x / (1 + x);
        const v = Math.round(255 * srgb(Math.min(Math.max(x, 0), 1)));
        out.data[i * 4 + k] = v;
        sum += v;
      }
      out.data[i * 4 + 3] = 255;
    }
    g.putImageData(out, 0, 0);
    canvas.dataset.state = "shown";
    canvas.dataset.mean = (sum / (3 * d.w * d.h)).toFixed(3);
  }

  function paintAll() {
    const canvases = document.querySelectorAll("canvas[data-hdr]");
    canvases.forEach(paint);
    evValue.textContent = (ev.value > 0 ? "+" : "") + ev.value + " EV";
    document.body.dataset.painted = String(canvases.length);
    document.body.dataset.ev = ev.value;
  }

  function readAddress() {
    const params = new URLSearchParams(location.hash.slice(1));
    if (params.has("ev") && isFinite(parseFloat(params.get("ev")))) ev.value = params.get("ev");
    if (params.get("op") === "reinhard" || params.get("op") === "clip") op.value = params.get("op");
  }

  function writeAddress() {
    history.replaceState(null, "", "#ev=" + ev.value + "&op=" + op.value);
  }

  ev.addEventListener("input", function () { paintAll(); writeAddress(); });
  op.addEventListener("change", function () { paintAll(); writeAddress(); });
  window.addEventListener("hashchange", function () { readAddress(); paintAll(); });

  document.querySelectorAll(".compare").forEach(function (compare) {
    compare.querySelectorAll("input.view-choice").forEach(function (radio) {
      radio.addEventListener("change", function () { compare.dataset.view = radio.value; });
    });
    compare.querySelectorAll("input.heat-choice").forEach(function (radio) {
      radio.addEventListener("change", function () {
        const figure = radio.closest(".heat-figure");
        figure.querySelector("img.heat").src = radio.dataset.file;
        figure.querySelector(".scale").textContent = radio.dataset.scale;
      });
    });
    const split = compare.querySelector("input.split");
    const top = compare.querySelector(".slider canvas.top");
    if (split && top) {
      const clip = function () { top.style.clipPath = "inset(0 0 0 " + split.value + "%)"; };
      split.addEventListener("input", clip);
      clip();
    }
  });
  // Flicker: the actual image on and off over the reference, twice a second.
  setInterval(function () {
    document.querySelectorAll('.compare[data-view="flicker"] .flicker canvas.top').forEach(function (c) {
      c.classList.toggle("hidden");
      const label = c.closest(".flicker").querySelector(".flicker-label");
      if (label) label.textContent = c.classList.contains("hidden") ? "reference" : "actual";
    });
  }, 500);

  document.querySelectorAll("img.heat").forEach(function (img) {
    const done = function () { img.dataset.state = img.naturalWidth > 0 ? "shown" : "missing"; };
    if (img.complete) done(); else { img.addEventListener("load", done); img.addEventListener("error", done); }
  });

  readAddress();
  Promise.all(Object.keys(images).map(decode)).then(paintAll, function (error) {
    document.body.dataset.error = String(error);
    paintAll();
  });
})();
)JS";
}

}  // namespace rmfx
