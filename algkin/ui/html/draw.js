// What every interactive page shares (a scene's, page.js; one with points solved together,
// groups.js): its controls, the SVG drawing of the parts, the state it publishes. Each page
// defines update(), which redraws it from its controls.
"use strict";
const SVGNS = "http://www.w3.org/2000/svg";
const controls = document.getElementById("controls");
const drawing = document.getElementById("drawing");
const statusLine = document.getElementById("status");
const stateOut = document.getElementById("state");
const THIN = {"vector-effect": "non-scaling-stroke"};  // a stroke's width in screen pixels, at any zoom

// A slider for spec ({name, lo, hi, value}), its value shown with its unit; returns it.
function addSlider(spec, unit) {
  const label = document.createElement("label");
  const shown = document.createElement("span");
  shown.className = "value";
  const slider = document.createElement("input");
  Object.assign(slider, {type: "range", min: spec.lo, max: spec.hi, step: "any", name: spec.name, id: "slider-" + spec.name});
  slider.value = spec.value;
  slider.addEventListener("input", () => { shown.textContent = slider.valueAsNumber.toPrecision(6) + unit; update(); });
  shown.textContent = slider.valueAsNumber.toPrecision(6) + unit;
  label.append(spec.name, shown);
  controls.append(label, slider);
  return slider;
}

// The assembly mode's choice among the options' texts, the k-th shown first; choose(k) on a change.
function addModeChoice(texts, k, choose) {
  const label = document.createElement("label");
  label.textContent = "assembly mode";
  const select = document.createElement("select");
  select.id = "branch";
  texts.forEach((text, i) => select.add(new Option(text, i)));
  select.value = k;
  select.addEventListener("input", () => { choose(Number(select.value)); update(); });
  controls.append(label, select);
}

// Starting values from the URL (page.html?angle=30&branch=right): each one moves its control as a
// user would, through the control's own input event. labels: the modes', in the choice's order.
function readQuery(labels, sliders) {
  for (const [name, text] of new URLSearchParams(location.search)) {
    if (name === "branch") {
      const k = labels.indexOf(text);
      const select = document.getElementById("branch");
      if (k >= 0 && select) { select.value = k; select.dispatchEvent(new Event("input")); }
    } else if (Object.prototype.hasOwnProperty.call(sliders, name)) {
      sliders[name].value = text;
      sliders[name].dispatchEvent(new Event("input"));
    }
  }
}

// The drawing's extent [xmin, xmax, ymin, ymax]: the finite ones of points ([x, y]), padded.
function bounds(points) {
  let [xmin, xmax, ymin, ymax] = [Infinity, -Infinity, Infinity, -Infinity];
  for (const [x, y] of points) {
    if (!isFinite(x) || !isFinite(y)) continue;
    xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymin = Math.min(ymin, y); ymax = Math.max(ymax, y);
  }
  if (!isFinite(xmin)) return [-1, 1, -1, 1];
  const pad = 0.08 * Math.max(xmax - xmin, ymax - ymin, 1e-9);
  return [xmin - pad, xmax + pad, ymin - pad, ymax + pad];
}

// An empty drawing showing the square around the extent box; SVG's y axis points down, so every
// part is drawn at (x, -y). Returns the square's side and the world units per screen pixel at full size.
function frame([xmin, xmax, ymin, ymax]) {
  const size = Math.max(xmax - xmin, ymax - ymin);
  drawing.replaceChildren();
  drawing.setAttribute("viewBox", `${xmin} ${-ymin - size} ${size} ${size}`);
  return [size, size / 640];
}

function element(name, attributes, text) {
  const node = document.createElementNS(SVGNS, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  if (text !== undefined) node.textContent = text;
  drawing.append(node);
  return node;
}

// A thin line from one point [x, y] to another.
function line(attributes, [x1, y1], [x2, y2]) {
  return element("line", {...THIN, ...attributes, x1, y1: -y1, x2, y2: -y2});
}

// The curve of a traced point through its places ([x, y], or null where it is not drawn: the pen lifts).
function trajectory(name, places, className) {
  let path = "";
  let pen = "M";
  for (const p of places) {
    if (!p) { pen = "M"; continue; }
    path += `${pen}${p[0]} ${-p[1]} `;
    pen = "L";
  }
  element("path", {...THIN, class: className, d: path, "stroke-width": 1.5, "data-trajectory": name});
}

function drawBars(pairs, points) {
  for (const [p, q] of pairs) line({class: "bar", "stroke-width": 4}, points[p], points[q]);
}

// A ground pivot's triangle under each of the points ids.
function drawGround(ids, points, unit) {
  for (const g of ids) {
    const [x, y] = points[g];
    const s = 9 * unit;
    element("polygon", {class: "ground", points: `${x},${-y} ${x - s},${-y + 1.7 * s} ${x + s},${-y + 1.7 * s}`});
  }
}

// A joint's circle and its name.
function drawJoint(name, [x, y], unit) {
  element("circle", {...THIN, class: "joint", "stroke-width": 1.5, r: 5 * unit, cx: x, cy: -y, "data-point": name});
  element("text", {class: "label", x: x + 7 * unit, y: -y - 7 * unit, "font-size": 14 * unit}, name);
}

// The state, for readers of the page (and its tests): exact doubles, as JSON; the status line says it.
function publish(state, words) {
  window.algkinState = state;
  stateOut.dataset.branch = state.branch;
  stateOut.dataset.values = JSON.stringify(state.values);
  stateOut.dataset.assembles = String(state.assembles);
  stateOut.dataset.blocked = state.blocked.join(" ");
  stateOut.dataset.positions = JSON.stringify(state.positions);
  statusLine.className = state.assembles ? "" : "blocked";
  statusLine.textContent = words;
}
