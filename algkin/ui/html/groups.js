// Points solved together: the input's slider -> each mode's precomputed path (MODEL.paths,
// from algkin's certified continuation) -> SVG. BUILT gives the points known from the input alone.
"use strict";
const SVGNS = "http://www.w3.org/2000/svg";
const controls = document.getElementById("controls");
const drawing = document.getElementById("drawing");
const statusLine = document.getElementById("status");
const stateOut = document.getElementById("state");
const input = MODEL.input;
let mode = MODEL.start;
let slider;

function addSlider() {
  const label = document.createElement("label");
  const shown = document.createElement("span");
  shown.className = "value";
  slider = document.createElement("input");
  Object.assign(slider, {type: "range", min: input.lo, max: input.hi, step: "any", name: input.name, id: "slider-" + input.name});
  slider.value = input.value;
  const unit = input.angle ? "°" : "";
  slider.addEventListener("input", () => { shown.textContent = slider.valueAsNumber.toPrecision(6) + unit; update(); });
  shown.textContent = slider.valueAsNumber.toPrecision(6) + unit;
  label.append(input.name, shown);
  controls.append(label, slider);
}

function addModeChoice() {
  const label = document.createElement("label");
  label.textContent = "assembly mode";
  const select = document.createElement("select");
  select.id = "branch";
  MODEL.paths.forEach((p, k) => select.add(new Option(p.label, k)));
  select.value = mode;
  select.addEventListener("input", () => { mode = Number(select.value); update(); });
  controls.append(label, select);
}

// The input's variables: an angle's cos and sin, a length itself.
function variables(t) {
  if (!input.angle) return {[input.name]: t};
  const radians = t * Math.PI / 180;
  return {["c_" + input.name]: Math.cos(radians), ["s_" + input.name]: Math.sin(radians)};
}

// Every point of path k at t (interpolated between its samples), or null outside its span.
function pose(k, t) {
  const path = MODEL.paths[k];
  const ts = path.t;
  if (!(t >= ts[0] && t <= ts[ts.length - 1])) return null;
  let lo = 0, hi = ts.length - 1;
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (ts[mid] <= t) lo = mid; else hi = mid; }
  const w = ts[hi] > ts[lo] ? (t - ts[lo]) / (ts[hi] - ts[lo]) : 0;
  const a = path.xy[lo], b = path.xy[hi];
  const known = built(t);  // exact, not interpolated
  return MODEL.points.map((_, i) => known[i] || [a[2 * i] + w * (b[2 * i] - a[2 * i]), a[2 * i + 1] + w * (b[2 * i + 1] - a[2 * i + 1])]);
}

function built(t) {
  const found = BUILT(variables(t)).points;
  const points = MODEL.points.map(() => null);
  MODEL.built.forEach((i, k) => { points[i] = found[k]; });
  return points;
}

function bounds() {
  let [xmin, xmax, ymin, ymax] = [Infinity, -Infinity, Infinity, -Infinity];
  const add = ([x, y]) => { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymin = Math.min(ymin, y); ymax = Math.max(ymax, y); };
  for (const path of MODEL.paths) for (const row of path.xy) for (let i = 0; i < row.length; i += 2) add([row[i], row[i + 1]]);
  for (let k = 0; k <= 72; k++) for (const p of built(input.lo + (input.hi - input.lo) * k / 72)) if (p) add(p);
  if (!isFinite(xmin)) return [-1, 1, -1, 1];
  const pad = 0.08 * Math.max(xmax - xmin, ymax - ymin, 1e-9);
  return [xmin - pad, xmax + pad, ymin - pad, ymax + pad];
}
const BOX = bounds();

function element(name, attributes, text) {
  const node = document.createElementNS(SVGNS, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  if (text !== undefined) node.textContent = text;
  drawing.append(node);
  return node;
}

// SVG's y axis points down: draw (x, -y).
function draw(points) {
  const [xmin, xmax, ymin, ymax] = BOX;
  const size = Math.max(xmax - xmin, ymax - ymin);
  const unit = size / 640;
  drawing.replaceChildren();
  drawing.setAttribute("viewBox", `${xmin} ${-ymin - size} ${size} ${size}`);
  const thin = {"vector-effect": "non-scaling-stroke"};
  MODEL.paths.forEach((path, k) => {
    for (const i of MODEL.traced) {
      const d = path.xy.map((row, j) => `${j ? "L" : "M"}${row[2 * i]} ${-row[2 * i + 1]}`).join(" ");
      element("path", {...thin, class: k === mode ? "trajectory" : "other", d, "stroke-width": 1.5, "data-trajectory": MODEL.points[i]});
      path.meets.forEach((at, end) => {
        if (at === null) return;
        const row = path.xy[end ? path.xy.length - 1 : 0];
        element("circle", {class: "meeting", r: 4 * unit, cx: row[2 * i], cy: -row[2 * i + 1], "data-meets": at});
      });
    }
  });
  const has = (...ids) => ids.every(i => points[i]);
  for (const [p, a, b] of MODEL.rails) {
    if (!has(a, b)) continue;
    const [x, y] = points[a], [dx, dy] = [points[b][0] - x, points[b][1] - y];
    const n = Math.hypot(dx, dy) || 1;
    element("line", {...thin, class: "guide", x1: x - 3 * size * dx / n, y1: -(y - 3 * size * dy / n), x2: x + 3 * size * dx / n, y2: -(y + 3 * size * dy / n)});
  }
  for (const ids of MODEL.platforms) {
    if (!has(...ids)) continue;
    element("polygon", {...thin, class: "platform", points: ids.map(i => `${points[i][0]},${-points[i][1]}`).join(" ")});
  }
  for (const [p, q] of MODEL.bars) {
    if (!has(p, q)) continue;
    element("line", {...thin, class: "bar", "stroke-width": 4, x1: points[p][0], y1: -points[p][1], x2: points[q][0], y2: -points[q][1]});
  }
  for (const g of MODEL.ground) {
    const [x, y] = points[g];
    const s = 9 * unit;
    element("polygon", {class: "ground", points: `${x},${-y} ${x - s},${-y + 1.7 * s} ${x + s},${-y + 1.7 * s}`});
  }
  MODEL.points.forEach((name, i) => {
    if (!points[i]) return;
    const [x, y] = points[i];
    element("circle", {...thin, class: "joint", "stroke-width": 1.5, r: 5 * unit, cx: x, cy: -y, "data-point": name});
    element("text", {class: "label", x: x + 7 * unit, y: -y - 7 * unit, "font-size": 14 * unit}, name);
  });
}

function update() {
  const t = slider.valueAsNumber;
  const now = pose(mode, t);
  const points = now || built(t);
  draw(points);
  const positions = {};
  MODEL.points.forEach((name, i) => { if (points[i]) positions[name] = points[i]; });
  const path = MODEL.paths[mode];
  const here = MODEL.paths.filter((_, k) => pose(k, t)).map(p => p.label);
  const span = `[${path.t[0].toPrecision(6)}, ${path.t[path.t.length - 1].toPrecision(6)}]`;
  const meets = path.meets.filter(m => m !== null).map(m => m.toPrecision(8));
  statusLine.className = now ? "" : "blocked";
  statusLine.textContent = now ? `${path.label}: assembles`
    : `${path.label}: not assembled here (${MODEL.blocked.join(", ")}): this mode exists for ${input.name} in ${span}`
      + (meets.length ? `, where it meets another mode at ${meets.join(" and ")}` : "")
      + (here.length ? `; modes here: ${here.join(", ")}` : "; no mode here");
  const values = {[input.name]: t};
  const blocked = now ? [] : MODEL.blocked;
  window.algkinState = {branch: path.label, values, assembles: !!now, blocked, positions};
  stateOut.dataset.branch = path.label;
  stateOut.dataset.values = JSON.stringify(values);
  stateOut.dataset.assembles = String(!!now);
  stateOut.dataset.blocked = blocked.join(" ");
  stateOut.dataset.positions = JSON.stringify(positions);
}

addSlider();
if (MODEL.paths.length > 1) addModeChoice();
update();

// Starting values from the URL (page.html?r1=6&branch=%2B%2B%2B): through the controls' own events.
for (const [name, text] of new URLSearchParams(location.search)) {
  if (name === "branch") {
    const k = MODEL.paths.findIndex(p => p.label === text);
    const select = document.getElementById("branch");
    if (k >= 0 && select) { select.value = k; select.dispatchEvent(new Event("input")); }
  } else if (name === input.name) {
    slider.value = text;
    slider.dispatchEvent(new Event("input"));
  }
}
