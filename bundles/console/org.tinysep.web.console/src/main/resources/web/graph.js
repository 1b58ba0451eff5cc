'use strict';
// The connection graph, drawn live as SVG from GET /api/devices: one box per device, in columns by depth (a device
// is one column right of the furthest device it consumes from), one arrow per connection. Each column is as wide as
// its longest label, measured in the page (a Sun SPOT's name is not cut off; at most MAX_W, then shortened).
const SVG = 'http://www.w3.org/2000/svg';
const BOX_W = 175, MAX_W = 420, BOX_H = 34, GAP_X = 60, GAP_Y = 12, PAD = 10, TEXT_X = 8;

function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

function subLabel(d) {
  return d.type + (d.room ? ' · ' + d.room.name : '');
}

// Measures rendered text widths at the sizes console.css gives #graph's texts (12px, 10px), in a hidden SVG of the
// page (same font); measure(text, size) until close().
function measurer() {
  const probe = svg('svg', {width: 0, height: 0, style: 'position:absolute;visibility:hidden'});
  document.body.append(probe);
  const measure = (text, size) => {
    const t = svg('text', {'font-size': size}, text);
    probe.append(t);
    const w = t.getComputedTextLength();
    t.remove();
    return w;
  };
  return {measure, close: () => probe.remove()};
}

// A label that fits a box of width w: shortened with … only beyond MAX_W.
function fit(text, size, w, measure) {
  if (measure(text, size) <= w - 2 * TEXT_X) return text;
  let n = text.length;
  while (n > 1 && measure(text.substring(0, n) + '…', size) > w - 2 * TEXT_X) n--;
  return text.substring(0, n) + '…';
}

function columns(devices) {
  const byUid = new Map(devices.map(d => [d.uid, d]));
  const depth = new Map();
  const visiting = new Set();
  const depthOf = d => {
    if (depth.has(d.uid)) return depth.get(d.uid);
    if (visiting.has(d.uid)) return 0; // a cycle: stop here
    visiting.add(d.uid);
    let n = 0;
    for (const c of d.connections) {
      const p = byUid.get(c.providerUid);
      if (p) n = Math.max(n, depthOf(p) + 1);
    }
    visiting.delete(d.uid);
    depth.set(d.uid, n);
    return n;
  };
  devices.forEach(depthOf);
  const cols = [];
  for (const d of devices) (cols[depth.get(d.uid)] = cols[depth.get(d.uid)] || []).push(d);
  return cols.map(c => c || []);
}

function draw(devices) {
  const m = measurer();
  try {
    drawMeasured(devices, m.measure);
  } finally {
    m.close();
  }
}

function drawMeasured(devices, measure) {
  const cols = columns(devices);
  const pos = new Map();
  const widths = new Map(devices.map(d => [d.uid, Math.max(measure(d.name, 12), measure(subLabel(d), 10))]));
  const colW = cols.map(col => Math.min(MAX_W, Math.max(BOX_W, ...col.map(d => Math.ceil(widths.get(d.uid)) + 2 * TEXT_X + 2))));
  const colX = colW.map((w, i) => PAD + colW.slice(0, i).reduce((a, b) => a + b + GAP_X, 0));
  const place = (col, x) => col.forEach((d, y) => pos.set(d.uid, {x: colX[x], y: PAD + y * (BOX_H + GAP_Y), w: colW[x]}));
  const mean = (uids, fallback) => {
    const ys = uids.map(u => pos.get(u)).filter(p => p).map(p => p.y);
    return ys.length ? ys.reduce((a, b) => a + b, 0) / ys.length : fallback;
  };
  // fewer crossings: each column in the order of the devices it consumes from, then the first column in the
  // order of its consumers
  cols.forEach((col, x) => {
    col.sort((a, b) => a.name.localeCompare(b.name));
    if (x > 0) {
      const key = new Map(col.map((d, i) => [d.uid, mean(d.connections.map(c => c.providerUid), 1e6 + i)]));
      col.sort((a, b) => key.get(a.uid) - key.get(b.uid));
    }
    place(col, x);
  });
  if (cols.length > 1) {
    const consumers = new Map();
    for (const d of devices) for (const c of d.connections) (consumers.get(c.providerUid) || consumers.set(c.providerUid, []).get(c.providerUid)).push(d.uid);
    const first = cols[0];
    const key = new Map(first.map((d, i) => [d.uid, mean(consumers.get(d.uid) || [], 1e6 + i)]));
    first.sort((a, b) => key.get(a.uid) - key.get(b.uid));
    place(first, 0);
  }
  const height = PAD * 2 + Math.max(1, ...cols.map(c => c.length)) * (BOX_H + GAP_Y);
  const width = PAD * 2 + colW.reduce((a, b) => a + b + GAP_X, 0);
  const root = svg('svg', {id: 'graph', width, height, viewBox: '0 0 ' + width + ' ' + height, role: 'img',
    'aria-label': 'connections between ' + devices.length + ' devices'});
  const defs = svg('defs', {});
  const marker = svg('marker', {id: 'arrow', viewBox: '0 0 10 10', refX: 10, refY: 5, markerWidth: 7, markerHeight: 7, orient: 'auto-start-reverse'});
  marker.append(svg('path', {d: 'M 0 0 L 10 5 L 0 10 z', fill: '#5b6875'}));
  defs.append(marker);
  root.append(defs);
  for (const d of devices) {
    for (const c of d.connections) {
      const from = pos.get(c.providerUid), to = pos.get(d.uid);
      if (!from || !to) continue;
      const x1 = from.x + from.w, y1 = from.y + BOX_H / 2, x2 = to.x, y2 = to.y + BOX_H / 2;
      const line = svg('path', {d: 'M ' + x1 + ' ' + y1 + ' C ' + (x1 + GAP_X / 2) + ' ' + y1 + ', ' + (x2 - GAP_X / 2) + ' ' + y2 + ', ' + x2 + ' ' + y2,
        class: c.vital ? 'edge vital' : 'edge optional', 'marker-end': 'url(#arrow)'});
      line.append(svg('title', {}, c.interface + (c.vital ? ' (vital)' : ' (optional)')));
      root.append(line);
    }
  }
  for (const d of devices) {
    const p = pos.get(d.uid);
    const link = svg('a', {href: '/devices.html#' + d.uid, class: 'node state-' + d.status.state});
    link.append(svg('rect', {x: p.x, y: p.y, width: p.w, height: BOX_H, rx: 5}));
    const long = widths.get(d.uid) > p.w - 2 * TEXT_X; // only beyond MAX_W
    link.append(svg('text', {x: p.x + TEXT_X, y: p.y + 14}, long ? fit(d.name, 12, p.w, measure) : d.name));
    link.append(svg('text', {x: p.x + TEXT_X, y: p.y + 28, class: 'sub'}, long ? fit(subLabel(d), 10, p.w, measure) : subLabel(d)));
    link.append(svg('title', {}, d.name + ' — ' + d.status.state + (d.status.detail ? ': ' + d.status.detail : '')
      + (d.provides.length ? '\nprovides ' + d.provides.join(', ') : '')));
    root.append(link);
  }
  Tiny.clear(document.getElementById('graph-box')).append(root);
}

async function refresh() {
  draw(await Tiny.api('GET', 'devices'));
}

async function init() {
  try {
    await Tiny.start('graph.html');
    await refresh();
    setInterval(() => refresh().catch(() => {}), 5000);
  } catch (e) {
    Tiny.fail('graph-box', e);
  }
}
init();
