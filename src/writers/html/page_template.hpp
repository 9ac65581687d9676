// The HTML page written by write_html_animation: layout, style and the small application
// script. Placeholders (each exactly once, in this order): @@TITLE@@ (HTML-escaped
// title), @@WARNING@@ (HTML-escaped banner of a run that did not finish, or empty), @@LIBS@@ (the
// inlined three.js, OrbitControls and Chart.js <script> elements), @@DATA@@ (the model and
// frames as JSON). Lengths in the data are in m, angles as unit quaternions (x, y, z, w).
#pragma once

namespace finseg::html {

inline constexpr const char* kPageTemplate = R"FINSEG_PAGE(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="finseg">
<title>@@TITLE@@</title>
<style>
  :root {
    --bg: #eef1f5; --panel: #ffffff; --ink: #1d2733; --muted: #5d6b7a; --line: #d5dce4;
    --accent: #1f6fb2; --accent-ink: #ffffff; --bad: #b3261e;
  }
  * { box-sizing: border-box; }
  html, body { margin: 0; height: 100%; background: var(--bg); color: var(--ink);
    font: 14px/1.4 "DejaVu Sans", "Segoe UI", Helvetica, Arial, sans-serif; }
  body { display: flex; flex-direction: column; min-height: 560px; }
  header { display: flex; align-items: baseline; gap: 16px; padding: 10px 18px;
    background: #17212b; color: #f3f6f9; }
  header h1 { margin: 0; font-size: 17px; font-weight: 600; letter-spacing: 0.2px; }
  header .sub { color: #a9b7c6; font-size: 12.5px; }
  header .brand { margin-left: auto; color: #7f93a8; font-size: 12px; }
  #runwarning { margin: 10px 18px 0; padding: 10px 14px; border-radius: 6px; font-weight: 700;
    background: #fde2e1; color: #9b1c1c; border: 2px solid #c00000; }
  #runwarning:empty { display: none; }
  #error { display: none; margin: 10px 18px 0; padding: 10px 14px; border-radius: 6px;
    background: #fde8e6; color: var(--bad); border: 1px solid #f3b8b3; white-space: pre-wrap; }
  main { flex: 1; display: flex; gap: 12px; padding: 12px 18px 0; min-height: 0; }
  .card { background: var(--panel); border: 1px solid var(--line); border-radius: 8px;
    box-shadow: 0 1px 2px rgba(20, 30, 40, 0.06); position: relative; min-width: 0; }
  #view { flex: 1.45; overflow: hidden; }
  #view canvas { position: absolute; left: 0; top: 0; display: block; cursor: grab; }
  #view canvas:active { cursor: grabbing; }
  .overlay { position: absolute; pointer-events: none; font-size: 12px; color: var(--muted); }
  #legend { top: 10px; left: 12px; background: rgba(255, 255, 255, 0.88); padding: 7px 10px;
    border-radius: 6px; border: 1px solid var(--line); line-height: 1.6; }
  #legend .sw { display: inline-block; width: 11px; height: 11px; border-radius: 2px;
    margin-right: 5px; vertical-align: -1px; border: 1px solid rgba(0, 0, 0, 0.25); }
  #legend .row { white-space: nowrap; }
  #legend .items { display: grid; grid-template-columns: repeat(2, auto); column-gap: 14px; }
  #hint { bottom: 8px; right: 12px; }
  #clock { top: 10px; right: 12px; font: 600 15px/1.2 "DejaVu Sans Mono", monospace;
    color: var(--ink); background: rgba(255, 255, 255, 0.88); padding: 6px 10px;
    border-radius: 6px; border: 1px solid var(--line); text-align: right; }
  #clock .small { font-weight: 400; font-size: 12px; color: var(--muted); }
  #side { flex: 1; display: flex; flex-direction: column; padding: 12px 14px 10px; }
  #side h2 { margin: 0 0 6px; font-size: 14px; font-weight: 600; }
  #chartbox { position: relative; flex: 1; min-height: 220px; }
  #current { margin-top: 8px; font: 13px/1.5 "DejaVu Sans Mono", monospace; color: var(--muted); }
  #current b { color: var(--ink); font-weight: 600; }
  #controls { display: flex; align-items: center; gap: 12px; margin: 12px 18px 14px;
    padding: 10px 14px; }
  button svg { display: inline-block; vertical-align: -2px; }
  button { font: inherit; border: 1px solid var(--line); background: #f7f9fb; color: var(--ink);
    border-radius: 6px; padding: 6px 10px; cursor: pointer; min-width: 38px; }
  button:hover { background: #edf1f5; }
  button.primary { background: var(--accent); color: var(--accent-ink); border-color: var(--accent);
    min-width: 92px; font-weight: 600; }
  button.primary:hover { background: #195d96; }
  #slider { flex: 1; accent-color: var(--accent); }
  label { color: var(--muted); font-size: 13px; white-space: nowrap; }
  select { font: inherit; padding: 4px 6px; border-radius: 6px; border: 1px solid var(--line); }
  #status { font: 13px "DejaVu Sans Mono", monospace; min-width: 150px; text-align: right; }
  #side.hidden, .hidden { display: none; }
  .extrabox { position: relative; flex: 1; min-height: 180px; margin-top: 10px; }
</style>
</head>
<body>
<header>
  <h1 id="title"></h1><span class="sub" id="subtitle"></span>
  <span class="brand">finseg &middot; finite-segment simulation</span>
</header>
<div id="runwarning" role="alert">@@WARNING@@</div>
<div id="error" role="alert"></div>
<main>
  <div class="card" id="view">
    <div class="overlay" id="legend"></div>
    <div class="overlay" id="clock"></div>
    <div class="overlay" id="hint">drag: rotate &middot; right-drag / shift-drag: pan &middot; wheel: zoom &middot; space: play/pause &middot; &larr; &rarr;: step</div>
  </div>
  <div class="card" id="side">
    <h2 id="charttitle"></h2>
    <div id="chartbox"><canvas id="chart"></canvas></div>
    <div id="current"></div>
    <div id="extracharts"></div>
  </div>
</main>
<div class="card" id="controls">
  <button id="first" title="first frame"><svg viewBox="0 0 16 16" width="14" height="14"><rect x="2" y="3" width="2" height="10" fill="currentColor"/><path d="M14 3v10L5 8z" fill="currentColor"/></svg></button>
  <button id="prev" title="previous frame (&larr;)"><svg viewBox="0 0 16 16" width="14" height="14"><path d="M12 3v10L4 8z" fill="currentColor"/></svg></button>
  <button id="play" class="primary" title="play / pause (space)"></button>
  <button id="next" title="next frame (&rarr;)"><svg viewBox="0 0 16 16" width="14" height="14"><path d="M4 3v10l8-5z" fill="currentColor"/></svg></button>
  <input type="range" id="slider" min="0" max="0" value="0" step="1" aria-label="frame">
  <label>speed <select id="speed">
    <option value="5">5 frames/s</option><option value="10">10 frames/s</option>
    <option value="24">24 frames/s</option><option value="30" selected>30 frames/s</option>
    <option value="60">60 frames/s</option><option value="120">120 frames/s</option>
  </select></label>
  <label><input type="checkbox" id="loop" checked> loop</label>
  <button id="resetview" title="show the whole motion from the default direction">reset view</button>
  <span id="status" data-frame="0" data-frames="0" data-rendered="0" data-advanced="0" data-drawn="-1" data-playing="0" data-error="">loading&hellip;</span>
</div>
@@LIBS@@
<script id="finseg-data" type="application/json">@@DATA@@</script>
<script>
(function () {
  "use strict";
  var st = window.finseg = { frame: 0, frameCount: 0, playing: false, rendered: 0, advanced: 0,
                            error: "" };
  var statusEl = document.getElementById("status");

  function fail(msg) {
    st.error = String(msg);
    var box = document.getElementById("error");
    box.style.display = "block";
    box.textContent = "The animation could not be shown: " + st.error;
    statusEl.setAttribute("data-error", st.error);
    statusEl.textContent = "error";
  }
  window.addEventListener("error", function (e) { fail(e.message || "script error"); });

  // "name [unit]" -> {name, unit}
  function splitLabel(label) {
    var m = /^(.*?)\s*\[(.*)\]\s*$/.exec(label || "");
    return m ? { name: m[1], unit: m[2] } : { name: label || "", unit: "" };
  }
  function decimalsFor(range) {
    if (!(range > 0)) return 3;
    return Math.max(0, Math.min(8, 2 - Math.floor(Math.log10(range))));
  }
  function niceStep(x) {
    var p = Math.pow(10, Math.floor(Math.log10(x))), f = x / p;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
  }
  function fmtLength(m) {
    var a = Math.abs(m);
    if (a >= 1) return +m.toPrecision(4) + " m";
    if (a >= 1e-3) return +(m * 1e3).toPrecision(4) + " mm";
    return +(m * 1e6).toPrecision(4) + " \u00b5m";
  }

  var D;
  try {
    D = JSON.parse(document.getElementById("finseg-data").textContent);
  } catch (e) { fail("embedded data is not valid JSON: " + e.message); return; }

  var N = D.frames.t.length, B = D.bodies.panel.length;
  st.frameCount = N;
  statusEl.setAttribute("data-frames", String(N));
  document.getElementById("title").textContent = D.title;
  document.title = D.title;
  var tl = splitLabel(D.timeLabel);
  var tRange = N > 1 ? Math.abs(D.frames.t[N - 1] - D.frames.t[0]) : 0;
  var tDec = decimalsFor(tRange);
  document.getElementById("subtitle").textContent =
    B + " segments \u00b7 " + N + " frames \u00b7 " + tl.name + " " +
    D.frames.t[0].toFixed(tDec) + "\u2026" + D.frames.t[N - 1].toFixed(tDec) + " " + tl.unit +
    " \u00b7 lengths in m";

  if (typeof THREE === "undefined") { fail("three.js did not load"); return; }

  // ---- 3-D scene --------------------------------------------------------------------
  var PALETTE = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948",
                 "#b07aa1", "#ff9da7", "#9c755f", "#86bcb6", "#d4a6c8", "#8cd17d"];
  var FIXED = "#9aa0a6";
  var view = document.getElementById("view");
  var renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) { fail("WebGL is not available in this browser (" + e.message + ")"); return; }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf6f8fb, 1);
  view.insertBefore(renderer.domElement, view.firstChild);

  var scene = new THREE.Scene();
  // Bounds over all frames: centroids padded by the largest segment's half-diagonal.
  var maxHalf = 0, i, k, v;
  for (i = 0; i < B; ++i) {
    var ol = D.bodies.outline[i];
    for (v = 0; v < ol.length; v += 2) {
      maxHalf = Math.max(maxHalf, Math.hypot(ol[v], ol[v + 1], 0.5 * D.bodies.thickness[i]));
    }
  }
  var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (var f = 0; f < N; ++f) {
    var P = D.frames.p[f];
    for (i = 0; i < P.length; ++i) {
      lo[i % 3] = Math.min(lo[i % 3], P[i]); hi[i % 3] = Math.max(hi[i % 3], P[i]);
    }
  }
  for (k = 0; k < 3; ++k) {
    if (!isFinite(lo[k])) { lo[k] = 0; hi[k] = 0; }
    lo[k] -= maxHalf; hi[k] += maxHalf;
  }
  var center = new THREE.Vector3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  var radius = Math.max(1e-6, 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));

  var camera = new THREE.PerspectiveCamera(35, 1, radius / 200, radius * 200);
  camera.up.set(0, 0, 1);
  var viewDir = new THREE.Vector3(0.55, -1.5, 0.75).normalize();
  // Puts the whole motion's bounding sphere in view, from the default direction.
  function frameAll() {
    var vHalf = (camera.fov * Math.PI) / 360;
    var hHalf = Math.atan(Math.tan(vHalf) * camera.aspect);
    var dist = (1.08 * radius) / Math.sin(Math.min(vHalf, hHalf));
    camera.position.copy(center).addScaledVector(viewDir, dist);
    camera.lookAt(center);
    if (controls) { controls.target.copy(center); controls.update(); }
  }
  scene.add(camera);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x7d8896, 0.75));
  var sun = new THREE.DirectionalLight(0xffffff, 0.55);
  sun.position.set(0.4, -0.3, 1.0);
  camera.add(sun);
  var sky = new THREE.DirectionalLight(0xffffff, 0.3);
  sky.position.set(-0.5, 0.8, 1.5);
  scene.add(sky);

  // The grid lies in the world x-y plane, just below the lowest point.
  // Ground grid covering the x-y extent of the motion with a margin.
  var span = Math.max(hi[0] - lo[0], hi[1] - lo[1], 0.2 * radius);
  var gridStep = niceStep(span / 8);
  var gridCount = Math.max(4, Math.ceil((1.5 * span) / gridStep));
  if (gridCount % 2) gridCount++;
  var grid = new THREE.GridHelper(gridCount * gridStep, gridCount, 0xb9c3ce, 0xdde3ea);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.round(center.x / gridStep) * gridStep,
                    Math.round(center.y / gridStep) * gridStep, lo[2] - 0.02 * radius);
  scene.add(grid);
  // World axes at the origin when it lies within the scene, else at the low corner.
  var axes = new THREE.AxesHelper(gridStep);
  var inside = lo[0] <= 0 && hi[0] >= 0 && lo[1] <= 0 && hi[1] >= 0 && lo[2] <= 0 && hi[2] >= 0;
  if (inside) axes.position.set(0, 0, 0); else axes.position.set(lo[0], lo[1], lo[2]);
  axes.material.depthTest = false;
  axes.renderOrder = 5;
  scene.add(axes);

  var meshes = [], panelsSeen = {}, anyFixed = false;
  for (i = 0; i < B; ++i) {
    var fixed = D.bodies.fixed[i] === 1, panel = D.bodies.panel[i];
    var colour = new THREE.Color(fixed ? FIXED : PALETTE[((panel % PALETTE.length) + PALETTE.length) % PALETTE.length]);
    if (fixed) anyFixed = true; else panelsSeen[panel] = true;
    // The segment's prism: its mid-surface polygon extruded through the thickness.
    var outline = D.bodies.outline[i], th = D.bodies.thickness[i], corners = [];
    for (v = 0; v < outline.length; v += 2) corners.push(new THREE.Vector2(outline[v], outline[v + 1]));
    var geo = new THREE.ExtrudeBufferGeometry(new THREE.Shape(corners),
                                              { depth: th, bevelEnabled: false });
    geo.translate(0, 0, -0.5 * th);
    var mesh = new THREE.Mesh(geo, new THREE.MeshStandardMaterial({
      color: colour, roughness: 0.62, metalness: 0.0,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
    var edges = new THREE.LineSegments(new THREE.EdgesGeometry(geo),
      new THREE.LineBasicMaterial({ color: colour.clone().multiplyScalar(0.55),
                                    transparent: true, opacity: 0.7 }));
    mesh.add(edges);
    scene.add(mesh);
    meshes.push(mesh);
  }

  var maxContacts = 0;
  var C = D.frames.c;
  for (f = 0; f < N; ++f) maxContacts = Math.max(maxContacts, C[f].length / 3);
  var contactGeo = null;
  if (maxContacts > 0) {
    contactGeo = new THREE.BufferGeometry();
    contactGeo.setAttribute("position",
      new THREE.BufferAttribute(new Float32Array(3 * maxContacts), 3));
    var dot = document.createElement("canvas");
    dot.width = dot.height = 32;
    var dc = dot.getContext("2d");
    dc.beginPath(); dc.arc(16, 16, 13, 0, 2 * Math.PI);
    dc.fillStyle = "#d62728"; dc.fill();
    dc.lineWidth = 3; dc.strokeStyle = "#ffffff"; dc.stroke();
    var pts = new THREE.Points(contactGeo, new THREE.PointsMaterial({
      size: 11, sizeAttenuation: false, depthTest: false, transparent: true,
      map: new THREE.CanvasTexture(dot), alphaTest: 0.3 }));
    pts.renderOrder = 10;
    scene.add(pts);
  }

  // Legend: panel colours, fixed bodies, grid spacing, axes.
  var legend = document.getElementById("legend");
  var html = '<div class="items">';
  Object.keys(panelsSeen).map(Number).sort(function (a, b) { return a - b; }).forEach(function (p) {
    html += '<div class="row"><span class="sw" style="background:' +
      PALETTE[((p % PALETTE.length) + PALETTE.length) % PALETTE.length] + '"></span>panel ' + (p + 1) + "</div>";
  });
  if (anyFixed) html += '<div class="row"><span class="sw" style="background:' + FIXED + '"></span>fixed</div>';
  if (maxContacts > 0) html += '<div class="row"><span class="sw" style="background:#d62728;border-radius:50%"></span>contact</div>';
  html += "</div><div>grid spacing " + fmtLength(gridStep) + "</div>" +
    '<div>axes <span style="color:#e0453a">x</span> <span style="color:#3fa34d">y</span> ' +
    '<span style="color:#2f6fd6">z</span> (world)</div>';
  legend.innerHTML = html;

  var controls = null;
  if (typeof THREE.OrbitControls === "function") {
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.copy(center);
    controls.screenSpacePanning = true;
    controls.enableKeys = false;
    controls.update();
    controls.addEventListener("change", function () { render(); });
  }
  camera.lookAt(center);

  function resize() {
    var w = Math.max(50, view.clientWidth), h = Math.max(50, view.clientHeight);
    renderer.setSize(w, h, false);
    renderer.domElement.style.width = w + "px";
    renderer.domElement.style.height = h + "px";
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    if (chart) chart.resize();
    (extras || []).forEach(function (e) { e.chart.resize(); });
    render();
  }
  // Self-test mode (URL ?selftest=1, used by the browser test): after each render, count
  // the canvas pixels that differ from the background, i.e. what WebGL really drew.
  var selftest = /[?&]selftest=1/.test(location.search);
  function countDrawn() {
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    var px = new Uint8Array(4 * w * h), n = 0;
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    for (var q = 0; q < px.length; q += 4) {
      if (Math.abs(px[q] - 0xf6) + Math.abs(px[q + 1] - 0xf8) + Math.abs(px[q + 2] - 0xfb) > 24) n++;
    }
    return n;
  }
  function render() {
    renderer.render(scene, camera);
    st.rendered++;
    statusEl.setAttribute("data-rendered", String(st.rendered));
    if (selftest) statusEl.setAttribute("data-drawn", String(countDrawn()));
  }

  // ---- force curve ------------------------------------------------------------------
  var cv = D.curve, hasCurve = cv.x.length > 0;
  var xl = splitLabel(cv.xLabel), yl = splitLabel(cv.yLabel);
  var chart = null, xDec = 3, yDec = 3;
  var currentEl = document.getElementById("current");
  var extras = [];  // further curves below the chart (chamber pressures)
  if (!hasCurve) {
    if (D.curves.length === 0) document.getElementById("side").classList.add("hidden");
    document.getElementById("chartbox").classList.add("hidden");
  } else if (typeof Chart === "undefined") {
    fail("Chart.js did not load");
    return;
  } else {
    document.getElementById("charttitle").textContent =
      (yl.name || "y") + " against " + (xl.name || "x");
    var xmin = Math.min.apply(null, cv.x), xmax = Math.max.apply(null, cv.x);
    var ymin = Math.min.apply(null, cv.y), ymax = Math.max.apply(null, cv.y);
    xDec = decimalsFor(xmax - xmin); yDec = decimalsFor(ymax - ymin);
    var pts2 = cv.x.map(function (x, j) { return { x: x, y: cv.y[j] }; });
    var marks = cv.marks || [];
    var markerLine = {
      id: "finsegMarker",
      afterDatasetsDraw: function (ch) {
        marks.forEach(function (m) {
          var mx = ch.scales.x.getPixelForValue(m.x), my = ch.scales.y.getPixelForValue(m.y);
          ch.ctx.save();
          ch.ctx.fillStyle = "#111111";
          ch.ctx.beginPath(); ch.ctx.arc(mx, my, 5, 0, 2 * Math.PI); ch.ctx.fill();
          ch.ctx.font = "12px DejaVu Sans, sans-serif";
          ch.ctx.textAlign = mx > (ch.scales.x.left + ch.scales.x.right) / 2 ? "right" : "left";
          ch.ctx.fillText(m.label, mx + (ch.ctx.textAlign === "right" ? -8 : 8), my - 8);
          ch.ctx.restore();
        });
        var p = pts2[Math.min(st.frame, pts2.length - 1)];
        var xs = ch.scales.x, ys = ch.scales.y, ctx = ch.ctx;
        var px = xs.getPixelForValue(p.x);
        ctx.save();
        ctx.strokeStyle = "rgba(214,39,40,0.55)";
        ctx.setLineDash([4, 4]);
        ctx.lineWidth = 1;
        ctx.beginPath(); ctx.moveTo(px, ys.top); ctx.lineTo(px, ys.bottom); ctx.stroke();
        ctx.restore();
      }
    };
    chart = new Chart(document.getElementById("chart").getContext("2d"), {
      type: "scatter",
      data: { datasets: [
        { label: cv.yLabel, data: pts2, showLine: true, borderColor: "#1f6fb2",
          backgroundColor: "#1f6fb2", borderWidth: 2, pointRadius: 0, pointHitRadius: 6,
          tension: 0 },
        { label: "current frame", data: [pts2[0]], showLine: false, pointRadius: 6,
          pointHoverRadius: 7, pointBackgroundColor: "#d62728", pointBorderColor: "#ffffff",
          pointBorderWidth: 2 }
      ] },
      options: {
        animation: false, responsive: true, maintainAspectRatio: false,
        interaction: { mode: "nearest", intersect: false },
        scales: {
          x: { type: "linear", title: { display: true, text: cv.xLabel, font: { size: 13 } },
               grid: { color: "#eef1f4" } },
          y: { title: { display: true, text: cv.yLabel, font: { size: 13 } },
               grid: { color: "#eef1f4" } }
        },
        plugins: {
          legend: { display: false },
          tooltip: { callbacks: { label: function (c) {
            return xl.name + " " + c.parsed.x.toFixed(xDec) + " " + xl.unit + ", " +
                   yl.name + " " + c.parsed.y.toFixed(yDec) + " " + yl.unit; } } }
        },
        onClick: function (evt, els, ch) {
          var x = ch.scales.x.getValueForPixel(evt.x), best = 0, bd = Infinity;
          for (var j = 0; j < pts2.length; ++j) {
            var d = Math.abs(pts2[j].x - x);
            if (d < bd) { bd = d; best = j; }
          }
          pause(); setFrame(best);
        }
      },
      plugins: [markerLine]
    });
  }

  if (D.curves.length > 0 && typeof Chart === "undefined") {
    fail("Chart.js did not load");
    return;
  }
  D.curves.forEach(function (c) {
    var box = document.createElement("div"), h = document.createElement("h2");
    var el = splitLabel(c.yLabel), xel = splitLabel(c.xLabel);
    h.textContent = (el.name || "y") + " against " + (xel.name || "x");
    box.className = "extrabox";
    var canvas = document.createElement("canvas");
    box.appendChild(canvas);
    var host = document.getElementById("extracharts");
    host.appendChild(h); host.appendChild(box);
    var pts = c.x.map(function (x, j) { return { x: x, y: c.y[j] }; });
    var ch = new Chart(canvas.getContext("2d"), {
      type: "scatter",
      data: { datasets: [
        { label: c.yLabel, data: pts, showLine: true, borderColor: "#2ca02c",
          backgroundColor: "#2ca02c", borderWidth: 2, pointRadius: 0, tension: 0 },
        { label: "current frame", data: [pts[0]], showLine: false, pointRadius: 6,
          pointBackgroundColor: "#d62728", pointBorderColor: "#ffffff", pointBorderWidth: 2 }
      ] },
      options: {
        animation: false, responsive: true, maintainAspectRatio: false,
        scales: {
          x: { type: "linear", title: { display: true, text: c.xLabel, font: { size: 13 } } },
          y: { title: { display: true, text: c.yLabel, font: { size: 13 } } }
        },
        plugins: { legend: { display: false } }
      }
    });
    extras.push({ chart: ch, pts: pts });
  });

  // ---- frames and playback ----------------------------------------------------------
  var slider = document.getElementById("slider"), playBtn = document.getElementById("play");
  var clock = document.getElementById("clock");
  slider.max = String(N - 1);

  function setFrame(n) {
    n = Math.max(0, Math.min(N - 1, n | 0));
    st.frame = n;
    var P = D.frames.p[n], Q = D.frames.q[n];
    for (var b = 0; b < B; ++b) {
      meshes[b].position.set(P[3 * b], P[3 * b + 1], P[3 * b + 2]);
      meshes[b].quaternion.set(Q[4 * b], Q[4 * b + 1], Q[4 * b + 2], Q[4 * b + 3]);
    }
    if (contactGeo) {
      var cp = C[n], arr = contactGeo.attributes.position.array;
      for (var j = 0; j < cp.length; ++j) arr[j] = cp[j];
      contactGeo.attributes.position.needsUpdate = true;
      contactGeo.setDrawRange(0, cp.length / 3);
    }
    slider.value = String(n);
    var tText = D.frames.t[n].toFixed(tDec) + " " + tl.unit;
    clock.innerHTML = tl.name + " " + tText + '<div class="small">frame ' + (n + 1) + " / " + N + "</div>";
    if (chart) {
      var p = { x: cv.x[n], y: cv.y[n] };
      chart.data.datasets[1].data = [p];
      chart.update("none");
      currentEl.innerHTML = xl.name + " <b>" + p.x.toFixed(xDec) + "</b> " + xl.unit +
        "<br>" + yl.name + " <b>" + p.y.toFixed(yDec) + "</b> " + yl.unit;
    }
    extras.forEach(function (e) {
      e.chart.data.datasets[1].data = [e.pts[Math.min(n, e.pts.length - 1)]];
      e.chart.update("none");
    });
    statusEl.textContent = "frame " + (n + 1) + " / " + N;
    statusEl.setAttribute("data-frame", String(n));
    render();
  }

  var PLAY_ICON = '<svg viewBox="0 0 16 16" width="13" height="13" style="vertical-align:-1px">' +
    '<path d="M4 2.5v11l9.5-5.5z" fill="currentColor"/></svg>';
  var PAUSE_ICON = '<svg viewBox="0 0 16 16" width="13" height="13" style="vertical-align:-1px">' +
    '<rect x="3.5" y="2.5" width="3" height="11" fill="currentColor"/>' +
    '<rect x="9.5" y="2.5" width="3" height="11" fill="currentColor"/></svg>';
  playBtn.innerHTML = PLAY_ICON + " Play";
  var fps = 30, acc = 0, last = 0, timer = null;
  var speedSel = document.getElementById("speed"), loopBox = document.getElementById("loop");
  function tick() {
    timer = null;
    if (!st.playing) return;
    var now = performance.now();
    acc += ((now - last) / 1000) * fps;
    last = now;
    var steps = Math.floor(acc);
    if (steps > 0) {
      acc -= steps;
      var n = st.frame + steps;
      if (n >= N) {
        if (loopBox.checked) n = n % N; else { setFrame(N - 1); pause(); return; }
      }
      st.advanced += steps;
      statusEl.setAttribute("data-advanced", String(st.advanced));
      setFrame(n);
    }
    timer = setTimeout(tick, Math.min(16, 500 / fps));
  }
  function play() {
    if (st.playing || N < 2) return;
    if (st.frame >= N - 1 && !loopBox.checked) setFrame(0);
    st.playing = true; acc = 0; last = performance.now();
    playBtn.innerHTML = PAUSE_ICON + " Pause";
    statusEl.setAttribute("data-playing", "1");
    timer = setTimeout(tick, 0);
  }
  function pause() {
    st.playing = false;
    if (timer !== null) { clearTimeout(timer); timer = null; }
    playBtn.innerHTML = PLAY_ICON + " Play";
    statusEl.setAttribute("data-playing", "0");
  }
  st.setFrame = setFrame; st.play = play; st.pause = pause;

  playBtn.addEventListener("click", function () { if (st.playing) pause(); else play(); });
  document.getElementById("first").addEventListener("click", function () { pause(); setFrame(0); });
  document.getElementById("prev").addEventListener("click", function () { pause(); setFrame(st.frame - 1); });
  document.getElementById("next").addEventListener("click", function () { pause(); setFrame(st.frame + 1); });
  slider.addEventListener("input", function () { pause(); setFrame(+slider.value); });
  speedSel.addEventListener("change", function () { fps = +speedSel.value; });
  document.addEventListener("keydown", function (e) {
    if (e.target && (e.target.tagName === "INPUT" || e.target.tagName === "SELECT")) return;
    if (e.code === "Space") { e.preventDefault(); if (st.playing) pause(); else play(); }
    else if (e.key === "ArrowRight") { pause(); setFrame(st.frame + 1); }
    else if (e.key === "ArrowLeft") { pause(); setFrame(st.frame - 1); }
  });
  document.getElementById("resetview").addEventListener("click", function () { frameAll(); render(); });
  window.addEventListener("resize", resize);

  // URL options: ?frame=N (start at frame N, 0-based), ?autoplay=0 (start paused).
  var startFrame = /[?&]frame=(\d+)/.exec(location.search);
  resize();
  frameAll();
  setFrame(startFrame ? +startFrame[1] : 0);
  if (!/[?&]autoplay=0/.test(location.search)) play();
})();
</script>
</body>
</html>
)FINSEG_PAGE";

}  // namespace finseg::html
