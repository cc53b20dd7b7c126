// rdisc console: fills the page rdisc wrote with what the server pushes over its WebSocket,
// and sends the forms' calls. No library: the page works offline.
"use strict";

const TRACE_ROWS = 500;   // rows kept in the byte trace
const PLOT_POINTS = 400;  // points kept in each output's plot

const details = JSON.parse(document.getElementById("rdis-details").textContent);
const status = document.querySelector("[data-rdis-status]");
const series = new Map();  // output name -> {field -> [[t, value], ...]}
const pending = new Map(); // call id -> its form
let socket = null;
let nextId = 1;

function element(tag, text, cls) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (cls) e.className = cls;
  return e;
}

function shown(value) {
  if (Array.isArray(value)) return "[" + value.map(shown).join(", ") + "]";
  if (typeof value === "number" && !Number.isInteger(value)) return String(Math.round(value * 1e6) / 1e6);
  return String(value);
}

// ---- the graph: a click on a node shows its details ------------------------------------------------

function showDetails(id) {
  const d = details[id];
  const box = document.querySelector("[data-rdis-details]");
  if (!d || !box) return;
  box.replaceChildren();
  box.dataset.shown = id;
  const head = element("h3", d.kind + " " + d.name);
  box.append(head);
  if (d.place) box.append(element("p", d.place, "place"));
  if (d.doc) box.append(element("p", d.doc, "doc"));
  const list = element("ul");
  for (const fact of d.facts) list.append(element("li", fact));
  box.append(list);
  const target = document.querySelector(`[data-rdis-${d.kind}="${CSS.escape(d.name)}"]`);
  if (target) {
    const link = element("a", "go to its " + (d.kind === "output" ? "panel" : "form"));
    link.href = "#";
    link.addEventListener("click", (ev) => { ev.preventDefault(); target.scrollIntoView(); target.classList.add("flash"); });
    box.append(link);
  }
}

for (const node of document.querySelectorAll("[data-rdis-graph] svg g.node")) {
  node.style.cursor = "pointer";
  node.addEventListener("click", (ev) => { ev.preventDefault(); showDetails(node.id); });
}

// ---- forms: each makes one call --------------------------------------------------------------------

for (const form of document.querySelectorAll("form")) {
  const kind = ["input", "interface", "primitive"].find((k) => form.hasAttribute("data-rdis-" + k));
  if (!kind) continue;
  form.addEventListener("submit", (ev) => {
    ev.preventDefault();
    const values = {};
    for (const field of form.querySelectorAll("input[name]")) {
      values[field.name] = field.type === "checkbox" ? field.checked : field.value;
    }
    const id = nextId++;
    const result = form.querySelector(".result");
    if (!socket || socket.readyState !== WebSocket.OPEN) {
      result.textContent = "not connected";
      result.className = "result failed";
      return;
    }
    pending.set(id, form);
    result.textContent = "…";
    result.className = "result";
    socket.send(JSON.stringify({ id, kind, name: form.getAttribute("data-rdis-" + kind), values }));
  });
}

function answered(message) {
  const form = pending.get(message.id);
  pending.delete(message.id);
  if (!form) return;
  const result = form.querySelector(".result");
  result.textContent = message.ok ? "done" : message.error + ": " + message.message;
  result.className = "result " + (message.ok ? "done" : "failed");
  if (message.ok && form.hasAttribute("data-rdis-raw")) showRaw(form, message);
}

// ---- the raw terminal: bytes typed as hex, sent as they are; the device's answer as it came ---------

const rawForm = document.querySelector("form[data-rdis-raw]");
if (rawForm) {
  rawForm.addEventListener("submit", (ev) => {
    ev.preventDefault();
    const result = rawForm.querySelector(".result");
    if (!socket || socket.readyState !== WebSocket.OPEN) {
      result.textContent = "not connected";
      result.className = "result failed";
      return;
    }
    const id = nextId++;
    pending.set(id, rawForm);
    result.textContent = "…";
    result.className = "result";
    const connection = rawForm.querySelector("select[name=connection]").value;
    socket.send(JSON.stringify({ id, kind: "raw", connection, hex: rawForm.querySelector("input[name=hex]").value }));
  });
}

// One line a way: `> 8e 16  |..|` what was written, `< 3a 98  |:.|` what came back (or that nothing did).
function showRaw(form, message) {
  const log = document.querySelector("[data-rdis-raw-log]");
  const connection = form.querySelector("select[name=connection]").value;
  const line = (direction, hex, text) => {
    const item = element("li", undefined, direction);
    item.append(element("span", connection + " " + (direction === "write" ? ">" : "<") + " ", "type"),
                element("span", hex, "hex"), element("span", text, "ascii"));
    log.append(item);
  };
  line("write", message.sent, message.sent_text);
  if (message.answer) line("read", message.answer, message.text);
  else log.append(element("li", "no answer", "note"));
}

// ---- what the server pushes ------------------------------------------------------------------------

function showOutput(message) {
  const panel = document.querySelector(`[data-rdis-output="${CSS.escape(message.name)}"]`);
  if (!panel) return;
  const count = panel.querySelector("[data-count]");
  count.textContent = String(Number(count.textContent) + 1);
  let fields = series.get(message.name);
  if (!fields) series.set(message.name, fields = {});
  for (const [name, value] of Object.entries(message.contents)) {
    const cell = panel.querySelector(`[data-field="${CSS.escape(name)}"]`);
    if (cell) cell.textContent = shown(value);
    if (typeof value === "number" || typeof value === "boolean") {
      const points = fields[name] || (fields[name] = []);
      points.push([message.t, Number(value)]);
      if (points.length > PLOT_POINTS) points.splice(0, points.length - PLOT_POINTS);
    }
  }
  panel.dataset.latest = JSON.stringify(message.contents);
  plot(panel.querySelector("canvas[data-plot]"), fields);
}

const COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"];

// Round values from lo to hi for an axis, about `count` of them, a step of 1, 2 or 5 times a
// power of ten (0.37 over 5 ticks: 0, 0.1, 0.2, 0.3).
function ticks(lo, hi, count) {
  const rough = (hi - lo) / count, power = 10 ** Math.floor(Math.log10(rough));
  const step = power * ([1, 2, 5, 10].find((m) => m * power >= rough) || 10);
  const out = [];
  for (let k = Math.ceil(lo / step); k * step <= hi + step * 1e-9; k++) out.push(Number((k * step).toPrecision(12)));
  return out;
}

function plot(canvas, fields) {
  if (!canvas) return;
  const g = canvas.getContext("2d");
  const w = canvas.width, h = canvas.height, left = 48, bottom = 16;
  g.clearRect(0, 0, w, h);
  const all = Object.values(fields).flat();
  if (!all.length) return;
  let t0 = Math.min(...all.map((p) => p[0])), t1 = Math.max(...all.map((p) => p[0]));
  let lo = Math.min(...all.map((p) => p[1])), hi = Math.max(...all.map((p) => p[1]));
  if (t1 === t0) t1 = t0 + 1;
  if (hi === lo) { hi += 1; lo -= 1; }
  const x = (t) => left + (t - t0) / (t1 - t0) * (w - left - 4);
  const y = (v) => 4 + (hi - v) / (hi - lo) * (h - bottom - 8);
  g.strokeStyle = "#bbb"; g.fillStyle = "#555"; g.font = "10px sans-serif";
  g.strokeRect(left, 4, w - left - 4, h - bottom - 8);
  g.strokeStyle = "#eee";  // gridlines at round values, labelled: value on the left, seconds below
  for (const v of ticks(lo, hi, 4)) {
    g.beginPath(); g.moveTo(left, y(v)); g.lineTo(w - 4, y(v)); g.stroke();
    g.fillText(shown(v), 2, y(v) + 3);
  }
  for (const t of ticks(t0, t1, 5)) {
    g.beginPath(); g.moveTo(x(t), 4); g.lineTo(x(t), h - bottom - 4); g.stroke();
    g.fillText(shown(t) + " s", x(t) - 8, h - 3);
  }
  Object.entries(fields).forEach(([name, points], i) => {
    g.strokeStyle = COLOURS[i % COLOURS.length];
    g.beginPath();
    points.forEach(([t, v], k) => (k ? g.lineTo(x(t), y(v)) : g.moveTo(x(t), y(v))));
    g.stroke();
    g.fillStyle = g.strokeStyle; g.fillText(name, left + 4 + 60 * i, 14);
  });
}

function showState(state, ages) {
  for (const row of document.querySelectorAll("[data-rdis-state] tr[data-name]")) {
    if (row.dataset.name in state) row.querySelector("[data-value]").textContent = shown(state[row.dataset.name]);
    if (ages && row.dataset.name in ages) {  // a sensor's: how old its value was when the state was pushed
      let age = row.querySelector("[data-age]");
      if (!age) {
        age = element("td");
        age.dataset.age = "";
        row.append(age);
      }
      const seconds = ages[row.dataset.name];
      age.textContent = seconds === null ? "never read" : `read ${seconds.toFixed(3)} s before`;
    }
  }
}

function showError(message) {
  const list = document.querySelector("[data-rdis-errors]");
  const item = element("li");
  item.append(element("span", message.t.toFixed(3) + " s ", "time"), element("b", message.error + ": "),
              element("span", message.message));
  list.prepend(item);
}

// The byte trace: paused, the lines that come are held (the console records them all the same) and
// shown when it is resumed; filtered, only the lines of one primitive's requests and replies show.
const tracePause = document.querySelector("[data-rdis-trace-pause]");
const traceHeld = document.querySelector("[data-rdis-trace-held]");
const traceFilter = document.querySelector("[data-rdis-trace-filter]");
let held = null;  // while paused: the lines that came, in order

function showIo(message) {
  if (held) {
    held.push(message);
    if (held.length > TRACE_ROWS) held.shift();
    traceHeld.textContent = `${held.length} held`;
    return;
  }
  const body = document.querySelector("[data-rdis-trace] tbody");
  const row = element("tr", undefined, message.direction);
  const arrow = { write: ">", read: "<", lines: "lines" }[message.direction];
  row.append(element("td", message.t.toFixed(3)), element("td", message.connection),
             element("td", arrow), element("td", message.data, "hex"), element("td", message.primitive || "", "type"));
  row.title = `${message.connection} ${arrow} ${message.data}`;  // as rdisc run --trace prints it
  row.dataset.primitive = message.primitive || "";
  row.hidden = !shownBy(row);
  body.prepend(row);
  while (body.rows.length > TRACE_ROWS) body.deleteRow(-1);
}

function shownBy(row) {
  return !traceFilter || !traceFilter.value || row.dataset.primitive === traceFilter.value;
}

if (tracePause) {
  tracePause.addEventListener("click", () => {
    if (held) {
      const waiting = held;
      held = null;
      traceHeld.textContent = "";
      tracePause.textContent = "Pause";
      waiting.forEach(showIo);
    } else {
      held = [];
      traceHeld.textContent = "0 held";
      tracePause.textContent = "Resume";
    }
  });
  traceFilter.addEventListener("change", () => {
    for (const row of document.querySelectorAll("[data-rdis-trace] tbody tr")) row.hidden = !shownBy(row);
  });
}

// ---- the simulated body: a top (x-y) and a side (x-z) view of the pushed link frames ----------------

const bodyShapes = document.getElementById("rdis-body");
const body = bodyShapes ? JSON.parse(bodyShapes.textContent) : null;
const PANEL = 300, HEAD = 18, MARGIN = 14;  // px: as page.py lays the views out
const VIEWS = { top: [0, 1], side: [0, 2] };  // the world axes each view shows, across and up
const ROUND = 24;                              // points on a drawn circle
let extent = null;  // [[lo x, lo y, lo z], [hi ...]] in m: all the body has covered, so a moving base moves

// v turned by the unit quaternion q = [w, x, y, z]
function rotate(q, v) {
  const [w, x, y, z] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2],
          v[2] + w * t[2] + x * t[1] - y * t[0]];
}

function circle(radius, z) {
  return Array.from({ length: ROUND }, (_, k) => {
    const a = 2 * Math.PI * k / ROUND;
    return [radius * Math.cos(a), radius * Math.sin(a), z];
  });
}

// Points of the shape in its own frame whose hull is its outline seen from any side (a sphere: its centre).
function corners(shape) {
  const [a, b, c] = shape.size;
  if (shape.kind === "box") {
    const out = [];
    for (const sx of [-1, 1]) for (const sy of [-1, 1]) for (const sz of [-1, 1]) out.push([sx * a / 2, sy * b / 2, sz * c / 2]);
    return out;
  }
  if (shape.kind === "cylinder") return circle(a, -b / 2).concat(circle(a, b / 2));
  return [[0, 0, 0]];
}

// The convex hull of 2-D points, anticlockwise (Andrew's monotone chain).
function hull(points) {
  const p = points.slice().sort((u, v) => u[0] - v[0] || u[1] - v[1]);
  if (p.length < 3) return p;
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const half = (list) => {
    const out = [];
    for (const q of list) {
      while (out.length >= 2 && cross(out[out.length - 2], out[out.length - 1], q) <= 0) out.pop();
      out.push(q);
    }
    out.pop();
    return out;
  };
  return half(p).concat(half(p.slice().reverse()));
}

// Each drawn shape in the world as it is now: its points (a sphere: its centre and radius).
function placedShapes(links) {
  return body.shapes.map((shape) => {
    const pose = links[shape.link];
    const turn = pose.slice(3);
    const place = (v) => {
      const inLink = rotate(shape.quat, v).map((x, i) => x + shape.at[i]);
      return rotate(turn, inLink).map((x, i) => x + pose[i]);
    };
    return { points: corners(shape).map(place), radius: shape.kind === "sphere" ? shape.size[0] : 0 };
  });
}

function grow(points, radius) {
  for (const p of points) {
    if (!extent) extent = [p.slice(), p.slice()];
    for (let i = 0; i < 3; i++) {
      extent[0][i] = Math.min(extent[0][i], p[i] - radius);
      extent[1][i] = Math.max(extent[1][i], p[i] + radius);
    }
  }
}

function showBody(message) {
  const view = document.querySelector("[data-rdis-body]");
  if (!view || !body) return;
  const links = message.links;
  const shapes = placedShapes(links);
  for (const s of shapes) grow(s.points, s.radius);
  grow(Object.values(links).map((pose) => pose.slice(0, 3)), 0);
  grow([[0, 0, 0]], 0);  // the world's origin and floor stay in view
  const span = Math.max(0.1, ...[0, 1, 2].map((i) => extent[1][i] - extent[0][i]));
  const scale = (PANEL - 2 * MARGIN) / span;  // px a metre, the same in both views
  for (const [name, [across, up]] of Object.entries(VIEWS)) {
    const g = view.querySelector(`g[data-view="${name}"]`);
    const mid = [across, up].map((i) => (extent[0][i] + extent[1][i]) / 2);
    const px = (p) => [PANEL / 2 + (p[across] - mid[0]) * scale, HEAD + PANEL / 2 - (p[up] - mid[1]) * scale];
    g.querySelector("[data-scale]").textContent = shown(Math.round(span * 1000) / 1000) + " m across";
    const [ox, oy] = px([0, 0, 0]).map((v) => v.toFixed(1));  // the floor; from above, the world's axes
    g.querySelector("path.ground").setAttribute("d", `M0,${oy}H${PANEL}` + (name === "top" ? `M${ox},${HEAD}V${HEAD + PANEL}` : ""));
    g.querySelectorAll("polygon[data-rdis-shape]").forEach((polygon, k) => {
      const s = shapes[k];
      const outline = s.radius
        ? circle(s.radius, 0).map((c) => { const p = s.points[0].slice(); p[across] += c[0]; p[up] += c[1]; return p; })
        : s.points;
      polygon.setAttribute("points", hull(outline.map(px)).map((q) => q.map((v) => v.toFixed(1)).join(",")).join(" "));
    });
    for (const line of g.querySelectorAll("line[data-rdis-joint]")) {
      const [parent, child] = body.joints[line.dataset.rdisJoint];
      const [x1, y1] = px(links[parent]), [x2, y2] = px(links[child]);
      Object.entries({ x1, y1, x2, y2 }).forEach(([k, v]) => line.setAttribute(k, v.toFixed(1)));
    }
    for (const link of g.querySelectorAll("g[data-rdis-link]")) {
      const pose = links[link.dataset.rdisLink];
      const [cx, cy] = px(pose);
      link.dataset.at = pose.slice(0, 3).map((v) => v.toFixed(4)).join(" ");  // where it is, in m
      const dot = link.querySelector("circle");
      dot.setAttribute("cx", cx.toFixed(1));
      dot.setAttribute("cy", cy.toFixed(1));
    }
  }
  for (const row of view.querySelectorAll("[data-rdis-joints] tr[data-name]")) {
    const value = message.joints[row.dataset.name];
    if (value !== undefined) row.querySelector("[data-value]").textContent = value.toFixed(4);
  }
  view.dataset.t = message.t;
}

function receive(message) {
  switch (message.type) {
    case "hello":
      showState(message.state, message.sensor_ages);
      message.trace.forEach(showIo);
      message.errors.forEach(showError);
      message.outputs.forEach(showOutput);
      break;
    case "output": showOutput(message); break;
    case "io": showIo(message); break;
    case "state": showState(message.state, message.sensor_ages); break;
    case "error": showError(message); break;
    case "result": answered(message); break;
    case "body": showBody(message); break;
  }
}

function connect() {
  // the console's credential, given in the address it printed: the WebSocket asks for it too
  const token = new URLSearchParams(location.search).get("token") || "";
  socket = new WebSocket(`ws://${location.host}/ws?token=${encodeURIComponent(token)}`);
  socket.addEventListener("open", () => { status.textContent = "connected"; status.className = "status up"; });
  socket.addEventListener("message", (ev) => receive(JSON.parse(ev.data)));
  socket.addEventListener("close", () => {
    status.textContent = "disconnected (the console stopped)";
    status.className = "status down";
  });
}

connect();
