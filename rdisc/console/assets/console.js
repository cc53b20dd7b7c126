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

function showState(state) {
  for (const row of document.querySelectorAll("[data-rdis-state] tr[data-name]")) {
    if (row.dataset.name in state) row.querySelector("[data-value]").textContent = shown(state[row.dataset.name]);
  }
}

function showError(message) {
  const list = document.querySelector("[data-rdis-errors]");
  const item = element("li");
  item.append(element("span", message.t.toFixed(3) + " s ", "time"), element("b", message.error + ": "),
              element("span", message.message));
  list.prepend(item);
}

function showIo(message) {
  const body = document.querySelector("[data-rdis-trace] tbody");
  const row = element("tr", undefined, message.direction);
  const arrow = { write: ">", read: "<", lines: "lines" }[message.direction];
  row.append(element("td", message.t.toFixed(3)), element("td", message.connection),
             element("td", arrow), element("td", message.data, "hex"));
  row.title = `${message.connection} ${arrow} ${message.data}`;  // as rdisc run --trace prints it
  body.prepend(row);
  while (body.rows.length > TRACE_ROWS) body.deleteRow(-1);
}

function receive(message) {
  switch (message.type) {
    case "hello":
      showState(message.state);
      message.trace.forEach(showIo);
      message.errors.forEach(showError);
      message.outputs.forEach(showOutput);
      break;
    case "output": showOutput(message); break;
    case "io": showIo(message); break;
    case "state": showState(message.state); break;
    case "error": showError(message); break;
    case "result": answered(message); break;
  }
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.addEventListener("open", () => { status.textContent = "connected"; status.className = "status up"; });
  socket.addEventListener("message", (ev) => receive(JSON.parse(ev.data)));
  socket.addEventListener("close", () => {
    status.textContent = "disconnected (the console stopped)";
    status.className = "status down";
  });
}

connect();
