(function () {
  "use strict";
  const errors = window.assurErrors = [];
  window.addEventListener("error", (event) => errors.push(String(event.message)));
  const data = JSON.parse(document.getElementById("assur-data").textContent);
  const svg = document.getElementById("mechanism");
  const NS = svg.namespaceURI;
  const W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height, PAD = 42;
  const slider = document.getElementById("angle");
  const readout = document.getElementById("readout");
  const n = data.angle.length;
  const SERIES = ["#2563eb", "#dc2626", "#059669", "#d97706", "#7c3aed", "#db2777",
    "#0891b2", "#65a30d", "#4b5563", "#9333ea", "#ea580c", "#0d9488", "#be123c"];
  // a series' line pattern, so that series differ on grey paper and for readers who
  // tell the hues apart poorly (the first six hues are nearly one grey, and blue and
  // violet one hue under deuteranopia): five patterns, coprime with the 13 hues,
  // so that a diagram of up to five series (most of them) repeats none
  const DASHES = ["none", "8 3", "2 3", "9 3 2 3", "9 3 2 3 2 3"];

  function el(name, attrs, parent) {
    const node = document.createElementNS(NS, name);
    set(node, attrs);
    if (parent) parent.appendChild(node);
    return node;
  }
  function set(node, attrs) {
    for (const key in attrs) node.setAttribute(key, attrs[key]);
  }
  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return "–";
    // round-off (a frictionless guide's 1e-14 N) reads as the zero it is
    return Math.abs(v) < 1e-9 ? "0" : String(Number(v.toPrecision(4)));
  }
  // a diagram's numbers are read, not copied: a minus sign, where the tables keep
  // the hyphen a spreadsheet reads
  const tick = (v) => fmt(v).replace(/-/g, "\u2212");

  // model (m, y up) to drawing (px, y down), one scale for the whole sweep
  const [bx0, bx1, by0, by1] = data.bounds;
  const k = Math.min((W - 2 * PAD) / (bx1 - bx0), (H - 2 * PAD) / (by1 - by0));
  const ox = (W - k * (bx1 - bx0)) / 2 - k * bx0;
  const oy = (H + k * (by1 - by0)) / 2 + k * by0;
  const X = (x) => ox + k * x, Y = (y) => oy - k * y;
  function at(name, i) {
    const p = data.points[name];
    return [X(p.x[i]), Y(p.y[i])];
  }
  const colour = {};
  for (const link of data.links) colour[link.name] = link.colour;

  const layer = {};
  for (const name of ["guides", "links", "blocks", "pivots", "joints", "marks",
    "forces", "labels"]) layer[name] = el("g", {class: name}, svg);

  // guides: a hatched rail on the frame, a slot (channel) in a moving link
  const guides = data.guides.map((g) => {
    const group = el("g", {"data-guide": g.joint}, layer.guides);
    const item = {g: g, frame: g.body === "ground"};
    if (item.frame) {
      item.hatch = el("polygon", {fill: "url(#hatch)"}, group);
      item.rail = el("line", {stroke: "#4b5563", "stroke-width": 2}, group);
      item.axis = el("line", {stroke: "#9ca3af", "stroke-width": 1,
        "stroke-dasharray": "8 3 2 3"}, group);
    } else {
      item.outer = el("line", {stroke: colour[g.body], "stroke-width": 15,
        "stroke-linecap": "round", "stroke-opacity": 0.45}, group);
      item.inner = el("line", {stroke: "#fff", "stroke-width": 7,
        "stroke-linecap": "round"}, group);
    }
    return item;
  });
  function drawGuide(item, i) {
    const g = item.g;
    const a = [X(g.x1[i]), Y(g.y1[i])], b = [X(g.x2[i]), Y(g.y2[i])];
    const ends = {x1: a[0], y1: a[1], x2: b[0], y2: b[1]};
    if (!item.frame) {
      set(item.outer, ends);
      set(item.inner, ends);
      return;
    }
    // the rail runs under the block, on the side facing down (or right) on screen
    let nx = g.uy[i], ny = g.ux[i];
    if (ny < 0 || (Math.abs(ny) < 1e-9 && nx < 0)) { nx = -nx; ny = -ny; }
    const h = 10, w = 7;
    set(item.axis, ends);
    set(item.rail, {x1: a[0] + nx * h, y1: a[1] + ny * h, x2: b[0] + nx * h,
      y2: b[1] + ny * h});
    set(item.hatch, {points: [a, b, b, a].map((p, j) => {
      const d = j < 2 ? h : h + w;
      return (p[0] + nx * d) + "," + (p[1] + ny * d);
    }).join(" ")});
  }

  // links: a bar between two points, a plate through three or more; a guide fixed in
  // a link counts as a point at its middle, so that the link reaches its slot
  const guideOf = {};
  for (const g of data.guides) guideOf[g.joint] = g;
  function anchor(a, i) {
    if (!a.guide) return at(a.name, i);
    const g = guideOf[a.name];
    return [X((g.x1[i] + g.x2[i]) / 2), Y((g.y1[i] + g.y2[i]) / 2)];
  }
  const links = data.links.map((l) => {
    let order = l.points.map((name) => ({name: name, guide: false}))
      .concat(l.guides.map((name) => ({name: name, guide: true})));
    if (order.length < 2) return null;
    const p = order.map((a) => anchor(a, 0));
    let area = 0;
    p.forEach((q, j) => {
      const r = p[(j + 1) % p.length];
      area += q[0] * r[1] - r[0] * q[1];
    });
    if (Math.abs(area) < 1e-3 * W * H) {
      // (nearly) on one line: a bar between the two points farthest apart
      let best = [0, 1], far = -1;
      for (let a = 0; a < p.length; a++) {
        for (let b = a + 1; b < p.length; b++) {
          const d = Math.hypot(p[a][0] - p[b][0], p[a][1] - p[b][1]);
          if (d > far) { far = d; best = [a, b]; }
        }
      }
      order = best.map((j) => order[j]);
    } else {
      const cx = p.reduce((sum, q) => sum + q[0], 0) / p.length;
      const cy = p.reduce((sum, q) => sum + q[1], 0) / p.length;
      order = order.map((a, j) => [Math.atan2(p[j][1] - cy, p[j][0] - cx), a])
        .sort((u, v) => u[0] - v[0]).map((u) => u[1]);
    }
    const attrs = {"data-link": l.name, stroke: l.colour, "stroke-linecap": "round",
      "stroke-linejoin": "round"};
    const node = order.length === 2
      ? el("line", Object.assign(attrs, {"stroke-width": 9, "stroke-opacity": 0.9}),
        layer.links)
      : el("polygon", Object.assign(attrs, {"stroke-width": 6, fill: l.colour,
        "fill-opacity": 0.2}), layer.links);
    return {node: node, order: order};
  }).filter((item) => item !== null);
  function drawLink(item, i) {
    const p = item.order.map((a) => anchor(a, i));
    if (item.order.length === 2) {
      set(item.node, {x1: p[0][0], y1: p[0][1], x2: p[1][0], y2: p[1][1]});
    } else {
      set(item.node, {points: p.map((q) => q.join(",")).join(" ")});
    }
  }

  const moving = (node, x, y, deg) => set(node, {transform:
    "translate(" + x + " " + y + ")" + (deg ? " rotate(" + deg + ")" : "")});
  const blocks = [], pivots = [], circles = [], labels = [], marks = [];
  const together = (a, b) => data.points[a].x.every((x, i) => x === null ||
    Math.hypot(x - data.points[b].x[i], data.points[a].y[i] - data.points[b].y[i]) <
    1e-6 * (bx1 - bx0));
  function label(name, offset) {
    const same = labels.find((item) => together(item.name, name));
    if (same) {
      same.node.textContent += ", " + name;
      return;
    }
    const text = el("text", {class: "label", dx: offset, dy: -offset}, layer.labels);
    text.textContent = name;
    labels.push({node: text, name: name});
  }
  for (const j of data.joints) {
    if (j.kind === "P" && !j.slot) {
      const group = el("g", {"data-block": j.name}, layer.blocks);
      el("rect", {x: -18, y: -10, width: 36, height: 20, rx: 3, fill: colour[j.second],
        "fill-opacity": 0.25, stroke: colour[j.second], "stroke-width": 2.5}, group);
      el("rect", {x: -18, y: -10, width: 36, height: 20, rx: 3, fill: "none",
        stroke: "#111827", "stroke-opacity": 0.25, "stroke-width": 1}, group);
      blocks.push({node: group, name: j.name, guide: guideOf[j.name]});
    } else {
      if (j.first === "ground" || j.second === "ground") {
        const group = el("g", {"data-pivot": j.name}, layer.pivots);
        el("polygon", {points: "0,0 -10,16 10,16", fill: "#e5e7eb", stroke: "#374151",
          "stroke-width": 1.5, "stroke-linejoin": "round"}, group);
        el("rect", {x: -16, y: 16, width: 32, height: 7, fill: "url(#hatch)"}, group);
        el("line", {x1: -16, y1: 16, x2: 16, y2: 16, stroke: "#374151",
          "stroke-width": 2}, group);
        pivots.push({node: group, name: j.name});
      }
      const circle = el("circle", {r: 5.5, fill: "#fff", stroke: "#111827",
        "stroke-width": 2, "data-joint": j.name}, layer.joints);
      circles.push({node: circle, name: j.name});
    }
    label(j.name, 9);
  }
  for (const name of data.extra_points) {
    const link = data.links.find((l) => l.points.includes(name));
    const dot = el("circle", {r: 4, fill: link ? link.colour : "#111827",
      "data-point": name}, layer.joints);
    circles.push({node: dot, name: name});
    label(name, 8);
  }
  if (data.forces) {
    for (const l of data.links) {
      if (!l.center) continue;
      const group = el("g", {"data-center": l.name}, layer.marks);
      el("circle", {r: 5, fill: "#fff", stroke: "#111827", "stroke-width": 1.3}, group);
      el("path", {d: "M0,0 L5,0 A5,5 0 0,1 0,5 Z M0,0 L-5,0 A5,5 0 0,1 0,-5 Z",
        fill: "#111827"}, group);
      marks.push({node: group, name: l.center});
    }
  }

  // reaction arrows: one scale for the whole sweep, stated by the bar in the corner
  const arrows = [];
  let perNewton = 0;
  if (data.forces) {
    let most = 0;
    for (const j of data.forces.joints) {
      for (const v of data.columns[j + ".F"]) if (v !== null) most = Math.max(most, v);
    }
    const BAR = 60;
    const raw = most * BAR / (0.24 * Math.min(W, H)) || 1;
    const mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const newtons = [1, 2, 5, 10].map((m) => m * mag)
      .find((s) => s >= raw * (1 - 1e-9));
    perNewton = BAR / newtons;
    for (const j of data.forces.joints) {
      const line = el("line", {stroke: data.forces.colour, "stroke-width": 2.2,
        "marker-end": "url(#arrowhead)", "data-force": j}, layer.forces);
      arrows.push({node: line, name: j});
    }
    const bar = el("g", {class: "scale"}, svg);
    el("line", {x1: 14, y1: H - 16, x2: 14 + BAR, y2: H - 16, stroke: data.forces.colour,
      "stroke-width": 2.2, "marker-end": "url(#arrowhead)"}, bar);
    const label = el("text", {x: 20 + BAR, y: H - 12, class: "label"}, bar);
    label.textContent = fmt(newtons) + " " + data.forces.unit;
    document.getElementById("force-note").textContent = "Arrows: the reaction at " +
      "each joint, the force of its first link on its second (the bar in the lower " +
      "left corner is " + fmt(newtons) + " " + data.forces.unit + "). Filled " +
      "circles mark the centres of mass.";
  }

  function drawMechanism(i) {
    for (const item of guides) drawGuide(item, i);
    for (const item of links) drawLink(item, i);
    for (const item of blocks) {
      const p = at(item.name, i), g = item.guide;
      const deg = g ? -Math.atan2(g.uy[i], g.ux[i]) * 180 / Math.PI : 0;
      moving(item.node, p[0], p[1], deg);
    }
    for (const item of pivots.concat(marks)) {
      const p = at(item.name, i);
      moving(item.node, p[0], p[1]);
    }
    for (const item of circles) {
      const p = at(item.name, i);
      set(item.node, {cx: p[0], cy: p[1]});
    }
    for (const item of labels) {
      const p = at(item.name, i);
      set(item.node, {x: p[0], y: p[1]});
    }
    for (const item of arrows) {
      const p = at(item.name, i);
      const fx = data.columns[item.name + ".Fx"][i];
      const fy = data.columns[item.name + ".Fy"][i];
      const shown = Math.hypot(fx, fy) * perNewton > 3;
      set(item.node, {x1: p[0], y1: p[1], x2: p[0] + fx * perNewton,
        y2: p[1] - fy * perNewton, visibility: shown ? "visible" : "hidden"});
    }
  }

  // the lowest and highest value of some series, nulls left out; a loop, as a
  // sweep spread into Math.min's arguments (100 000 positions) overflows the stack
  function extent(lists) {
    let lo = Infinity, hi = -Infinity;
    for (const values of lists) {
      for (const v of values) {
        if (v === null) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    return [lo, hi];
  }

  // diagrams against the driver position, with a marker at the current one
  function ticks(lo, hi, count, degrees) {
    const span = hi - lo;
    let step;
    if (degrees && span > 150) {
      step = span > 800 ? 180 : 90;
    } else {
      const raw = span / count, mag = Math.pow(10, Math.floor(Math.log10(raw)));
      step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw);
    }
    return step;
  }
  function chart(spec, where) {
    const CW = 480, CH = 250, m = {l: 58, r: 14, t: 10, b: 40};
    const figure = document.createElement("figure");
    const caption = document.createElement("figcaption");
    caption.textContent = spec.title;
    figure.appendChild(caption);
    const s = el("svg", {viewBox: "0 0 " + CW + " " + CH, id: spec.id, role: "img",
      "aria-label": spec.title}, figure);
    const legend = document.createElement("div");
    legend.className = "chart-legend";
    figure.appendChild(legend);
    document.getElementById(where || "charts").appendChild(figure);
    const xs = data.angle;
    const series = spec.series.map((item, j) => Object.assign({
      values: data.columns[item.key],
      colour: item.dashed ? "#111827" : SERIES[j % SERIES.length],
      pattern: item.dashed ? "5 4" : DASHES[j % DASHES.length]}, item));
    let [lo, hi] = extent(series.map((item) => item.values));
    if (!(hi - lo > 1e-12 * Math.max(1, Math.abs(hi)))) {
      const half = Math.abs(hi) * 0.1 || 1;
      lo -= half; hi += half;
    }
    const ystep = ticks(lo, hi, 5, false);
    lo = Math.floor(lo / ystep) * ystep; hi = Math.ceil(hi / ystep) * ystep;
    // the left margin fits the longest tick label (0.0015) beside the unit's, so
    // that the two do not overlap (about 6.7 px a character at 11 px)
    let longest = 0;
    for (let j = 0; lo + j * ystep <= hi + ystep * 1e-6 && j < 60; j++) {
      const y = lo + j * ystep;
      longest = Math.max(longest, fmt(Math.abs(y) < ystep * 1e-6 ? 0 : y).length);
    }
    m.l = Math.max(m.l, 28 + Math.ceil(6.7 * longest));
    const x0 = xs[0], x1 = xs[xs.length - 1] === x0 ? x0 + 1 : xs[xs.length - 1];
    const xa = Math.min(x0, x1), xb = Math.max(x0, x1);
    const px = (x) => m.l + (x - xa) / (xb - xa) * (CW - m.l - m.r);
    const py = (y) => CH - m.b - (y - lo) / (hi - lo) * (CH - m.t - m.b);
    const axis = el("g", {class: "axis"}, s);
    for (let y = lo, j = 0; y <= hi + ystep * 1e-6 && j < 60; y = lo + (++j) * ystep) {
      const zero = Math.abs(y) < ystep * 1e-6;
      el("line", {x1: m.l, x2: CW - m.r, y1: py(y), y2: py(y), stroke: zero ? "#9ca3af"
        : "#eef0f3", "stroke-width": 1}, axis);
      el("text", {x: m.l - 6, y: py(y) + 4, "text-anchor": "end"}, axis).textContent =
        tick(zero ? 0 : y);
    }
    const degrees = data.driver.unit === "deg";
    const xstep = ticks(xa, xb, 6, degrees);
    for (let x = Math.ceil(xa / xstep - 1e-9) * xstep, j = 0; x <= xb + 1e-9 && j < 60;
      x += xstep, j++) {
      el("line", {x1: px(x), x2: px(x), y1: m.t, y2: CH - m.b, stroke: "#eef0f3"},
        axis);
      el("text", {x: px(x), y: CH - m.b + 15, "text-anchor": "middle"}, axis)
        .textContent = tick(x);
    }
    el("rect", {x: m.l, y: m.t, width: CW - m.l - m.r, height: CH - m.t - m.b,
      fill: "none", stroke: "#d1d5db"}, axis);
    el("text", {x: (m.l + CW - m.r) / 2, y: CH - 6, "text-anchor": "middle"}, axis)
      .textContent = data.driver.label + " (" + data.driver.unit + ")";
    const middle = (m.t + CH - m.b) / 2;
    el("text", {x: 13, y: middle, "text-anchor": "middle",
      transform: "rotate(-90 13 " + middle + ")"}, axis).textContent = spec.unit;
    const cursor = el("line", {y1: m.t, y2: CH - m.b, stroke: "#6b7280",
      "stroke-dasharray": "3 3", class: "cursor"}, s);
    const dots = [];
    // positions left out (a crank that cannot go round) leave a gap in the line
    const gaps = new Set(data.gaps || []);
    for (const item of series) {
      let d = "", pen = "M";
      item.values.forEach((v, i) => {
        if (v === null) { pen = "M"; return; }
        if (gaps.has(i)) pen = "M";
        d += pen + px(xs[i]).toFixed(1) + "," + py(v).toFixed(1);
        pen = "L";
      });
      el("path", {d: d, fill: "none", stroke: item.colour, "stroke-width": item.dashed
        ? 1.6 : 2, "stroke-dasharray": item.pattern, "stroke-linejoin": "round"}, s);
      dots.push(el("circle", {r: 3.5, fill: item.colour, stroke: "#fff",
        "stroke-width": 1.2}, s));
      // the key shows the line as drawn, its colour and its pattern
      const key = document.createElement("span");
      const swatch = el("svg", {viewBox: "0 0 22 8", "aria-hidden": "true"}, key);
      el("line", {x1: 0, y1: 4, x2: 22, y2: 4, stroke: item.colour, "stroke-width":
        item.dashed ? 1.6 : 2, "stroke-dasharray": item.pattern}, swatch);
      key.appendChild(document.createTextNode(item.name));
      legend.appendChild(key);
    }
    return function mark(i) {
      set(cursor, {x1: px(xs[i]), x2: px(xs[i])});
      series.forEach((item, j) => {
        const v = item.values[i];
        set(dots[j], {cx: px(xs[i]), cy: v === null ? -10 : py(v),
          visibility: v === null ? "hidden" : "visible"});
      });
    };
  }
  const cursors = data.charts.filter((spec) => spec.series.length)
    .map((spec) => chart(spec));
  if (data.dynamics) {
    for (const spec of data.dynamics.charts) cursors.push(chart(spec, "dynamics-charts"));
  }

  // live tables of the values at the shown position
  const live = [];
  const value = (key, i) => key in data.columns ? data.columns[key][i]
    : data.points[key.slice(0, -2)][key.slice(-1)][i];
  // a header cell of a live table: a column's heading or a row's name
  function heading(text, scope, line) {
    const th = document.createElement("th");
    th.setAttribute("scope", scope);
    th.textContent = text;
    line.appendChild(th);
  }
  function liveTable(part) {
    if (!part.rows.length) return;
    const table = document.createElement("table");
    // what the table holds, for a screen reader: the card's heading says it to the eye
    const caption = document.createElement("caption");
    caption.className = "unseen";
    caption.textContent = part.caption;
    table.appendChild(caption);
    const tr = table.createTHead().insertRow();
    for (const text of part.head) heading(text, "col", tr);
    const body = table.createTBody();
    for (const row of part.rows) {
      const line = body.insertRow();
      heading(row.name, "row", line);
      for (const key of row.keys) live.push({cell: line.insertCell(), key: key});
    }
    document.getElementById("current").appendChild(table);
  }
  for (const part of [data.current.links, data.current.slides, data.current.joints,
    data.current.inertia]) {
    liveTable(part);
  }

  const rows = {};
  for (const row of document.querySelectorAll("#values tr[data-row]")) {
    rows[row.dataset.row] = row;
  }
  let current = null;
  function update(i) {
    drawMechanism(i);
    cursors.forEach((mark) => mark(i));
    for (const item of live) item.cell.textContent = fmt(value(item.key, i));
    const at = (value, unit) => fmt(value) + (unit === "deg" ? "°" : " " + unit);
    let text = data.driver.label + " " + at(data.angle[i], data.driver.unit);
    // the other drivers' positions: the abscissa is the first one's
    for (const other of data.driver.others) {
      text += " · " + other.name + " " + at(data.columns[other.key][i], other.unit);
    }
    if (data.forces) {
      for (const item of data.forces.balancing) {
        if (item.dashed) continue;
        text += " · " + item.name + " " + fmt(data.columns[item.key][i]) + " " +
          item.unit;
      }
    }
    readout.textContent = text;
    // a screen reader hears the position where the slider is, once per move: the
    // readout is an output, a live region, which Play changed 25 times a second
    slider.setAttribute("aria-valuetext", text);
    // the row shown is marked for a screen reader too, not only by its tint
    if (current) {
      current.classList.remove("shown");
      current.removeAttribute("aria-current");
    }
    current = rows[i] || null;
    if (current) {
      current.classList.add("shown");
      current.setAttribute("aria-current", "true");
    }
  }
  slider.addEventListener("input", () => update(Number(slider.value)));

  let timer = null;
  const play = document.getElementById("play");
  play.addEventListener("click", () => {
    if (timer) {
      clearInterval(timer);
      timer = null;
      play.textContent = "Play";
      return;
    }
    play.textContent = "Pause";
    timer = setInterval(() => {
      slider.value = String((Number(slider.value) + 1) % n);
      update(Number(slider.value));
    }, 40);
  });
  update(0);
  document.documentElement.dataset.ready = "true";
})();
