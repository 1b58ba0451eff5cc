'use strict';
// The connection graph, drawn live as SVG from GET /api/devices: one box per device, in columns by depth (a device
// is one column right of the furthest device it consumes from), one arrow per connection.
const SVG = 'http://www.w3.org/2000/svg';
const BOX_W = 175, BOX_H = 34, GAP_X = 60, GAP_Y = 12, PAD = 10;

function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
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
  const cols = columns(devices);
  const pos = new Map();
  const place = (col, x) => col.forEach((d, y) => pos.set(d.uid, {x: PAD + x * (BOX_W + GAP_X), y: PAD + y * (BOX_H + GAP_Y)}));
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
  const width = PAD * 2 + cols.length * (BOX_W + GAP_X);
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
      const x1 = from.x + BOX_W, y1 = from.y + BOX_H / 2, x2 = to.x, y2 = to.y + BOX_H / 2;
      const line = svg('path', {d: 'M ' + x1 + ' ' + y1 + ' C ' + (x1 + GAP_X / 2) + ' ' + y1 + ', ' + (x2 - GAP_X / 2) + ' ' + y2 + ', ' + x2 + ' ' + y2,
        class: c.vital ? 'edge vital' : 'edge optional', 'marker-end': 'url(#arrow)'});
      line.append(svg('title', {}, c.interface + (c.vital ? ' (vital)' : ' (optional)')));
      root.append(line);
    }
  }
  for (const d of devices) {
    const p = pos.get(d.uid);
    const link = svg('a', {href: '/devices.html#' + d.uid, class: 'node state-' + d.status.state});
    link.append(svg('rect', {x: p.x, y: p.y, width: BOX_W, height: BOX_H, rx: 5}));
    const label = d.name.length > 26 ? d.name.substring(0, 25) + '…' : d.name;
    link.append(svg('text', {x: p.x + 8, y: p.y + 14}, label));
    link.append(svg('text', {x: p.x + 8, y: p.y + 28, class: 'sub'}, d.type + (d.room ? ' · ' + d.room.name : '')));
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
