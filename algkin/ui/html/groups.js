// Points solved together: the input's slider -> each mode's precomputed path (MODEL.paths,
// from algkin's certified continuation) -> SVG. BUILT gives the points known from the input alone.
// The controls and the drawing of the parts are draw.js's.
"use strict";
const input = MODEL.input;
let mode = MODEL.start;

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

// The drawing's extent, fixed: every path, and the built points over the input's span.
function extent() {
  const points = MODEL.paths.flatMap(path => path.xy.flatMap(row => MODEL.points.map((_, i) => [row[2 * i], row[2 * i + 1]])));
  for (let k = 0; k <= 72; k++) points.push(...built(input.lo + (input.hi - input.lo) * k / 72).filter(p => p));
  return bounds(points);
}
const BOX = extent();

function draw(points) {
  const [size, unit] = frame(BOX);
  MODEL.paths.forEach((path, k) => {
    for (const i of MODEL.traced) {
      trajectory(MODEL.points[i], path.xy.map(row => [row[2 * i], row[2 * i + 1]]), k === mode ? "trajectory" : "other");
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
    line({class: "guide"}, [x - 3 * size * dx / n, y - 3 * size * dy / n], [x + 3 * size * dx / n, y + 3 * size * dy / n]);
  }
  for (const ids of MODEL.platforms) {
    if (!has(...ids)) continue;
    element("polygon", {...THIN, class: "platform", points: ids.map(i => `${points[i][0]},${-points[i][1]}`).join(" ")});
  }
  drawBars(MODEL.bars.filter(([p, q]) => has(p, q)), points);
  drawGround(MODEL.ground, points, unit);
  MODEL.points.forEach((name, i) => { if (points[i]) drawJoint(name, points[i], unit); });
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
  const words = now ? `${path.label}: assembles`
    : `${path.label}: not assembled here (${MODEL.blocked.join(", ")}): this mode exists for ${input.name} in ${span}`
      + (meets.length ? `, where it meets another mode at ${meets.join(" and ")}` : "")
      + (here.length ? `; modes here: ${here.join(", ")}` : "; no mode here");
  publish({branch: path.label, values: {[input.name]: t}, assembles: !!now, blocked: now ? [] : MODEL.blocked, positions}, words);
}

const slider = addSlider(input, input.angle ? "°" : "");
const labels = MODEL.paths.map(p => p.label);
if (MODEL.paths.length > 1) addModeChoice(labels, mode, k => { mode = k; });
update();
readQuery(labels, {[input.name]: slider});  // page.html?r1=6&branch=%2B%2B%2B
