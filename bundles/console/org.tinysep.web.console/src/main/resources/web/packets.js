'use strict';
// The packet log page: every packet received or sent (hex, the thesis's decimal notation as a tooltip, the decoded
// form from the bus radios' packet describers, or why it is not decoded; why a packet was rejected), live,
// filtered by node and kind; a search of the stored history.
let live = true;
const MAX_ROWS = 1000;

function row(p) {
  const tr = Tiny.el('tr', {class: p.note ? 'kind-PROBLEM' : null, 'data-seq': p.seq, 'data-node': p.node || ''},
    Tiny.el('td', {class: 'nowrap'}, Tiny.time(p.time)), Tiny.el('td', {}, p.direction), Tiny.el('td', {}, p.origin),
    Tiny.el('td', {class: 'mono', title: 'decimal: ' + p.decimal}, p.hex), p.decoded
      ? Tiny.el('td', {class: 'decoded'}, p.decoded)
      : Tiny.el('td', {class: 'undecoded'}, p.undecoded || ''), Tiny.el('td', {}, p.note));
  tr.packet = p;
  return tr;
}

function matches(p) {
  const node = nodeFilter();
  const kind = document.getElementById('kind').value;
  const kindOk = !kind || p.direction === kind || (kind === 'REJECTED' && p.note) || (kind === 'GOOD' && !p.note);
  return kindOk && (!node || p.origin === node || p.origin.startsWith(node + ' '));
}

// the node filter: "1.17" or "node 1.17" (a node address as the devices list shows it)
function nodeFilter() {
  const v = document.getElementById('node').value.trim();
  return v && !v.startsWith('node ') && /^[0-9A-Fa-f.]+$/.test(v) ? 'node ' + v : v;
}

function refilter() {
  if (!live) return;
  for (const tr of document.querySelectorAll('#packets tr')) tr.hidden = !matches(tr.packet);
}

function add(p) {
  if (!live) return;
  const body = document.getElementById('packets');
  const tr = row(p);
  tr.hidden = !matches(p);
  body.prepend(tr);
  while (body.children.length > MAX_ROWS) body.removeChild(body.lastChild);
}

function query(limit) {
  const p = new URLSearchParams();
  const iso = id => { const v = document.getElementById(id).value; return v ? new Date(v).toISOString() : ''; };
  for (const [key, value] of [['from', iso('from')], ['to', iso('to')], ['origin', nodeFilter()],
      ['kind', document.getElementById('kind').value], ['limit', limit || document.getElementById('limit').value]]) {
    if (value) p.set(key, value);
  }
  return 'packets?' + p;
}

function show(h, what) {
  const body = Tiny.clear(document.getElementById('packets'));
  for (const p of h.entries.slice().reverse()) body.append(row(p));
  refilter();
  document.getElementById('summary').textContent = what + ': ' + h.entries.length + ' of ' + h.matched + ' matching packets'
    + (h.damagedLines ? ' (' + h.damagedLines + ' damaged lines skipped)' : '');
}

async function init() {
  document.getElementById('search').addEventListener('submit', async ev => {
    ev.preventDefault();
    try { live = false; show(await Tiny.api('GET', query()), 'History'); }
    catch (e) { document.getElementById('summary').textContent = e.message; }
  });
  document.getElementById('live-mode').addEventListener('click', () => location.reload());
  document.getElementById('node').addEventListener('input', refilter);
  document.getElementById('kind').addEventListener('change', refilter);
  try {
    await Tiny.start('packets.html');
    Tiny.api('GET', 'devices').then(devices => { // the nodes to choose from
      const list = document.getElementById('nodes');
      for (const a of [...new Set(devices.map(d => d.nodeAddress).filter(a => a))].sort()) list.append(Tiny.el('option', {value: a}));
    }).catch(() => {});
    const h = await Tiny.api('GET', 'packets?limit=200');
    show(h, 'Live');
    Tiny.stream('packets', h.entries.length ? h.entries[h.entries.length - 1].seq : -1, add);
  } catch (e) {
    Tiny.fail('packets-box', e);
  }
}
init();
