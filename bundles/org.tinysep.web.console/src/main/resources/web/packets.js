'use strict';
// The packet log page: every packet received or sent (hex and the thesis's decimal notation, why a packet was
// rejected), live, filtered by node and kind; a search of the stored history.
let live = true;
const MAX_ROWS = 1000;

function row(p) {
  return Tiny.el('tr', {class: p.note ? 'kind-PROBLEM' : null, 'data-seq': p.seq},
    Tiny.el('td', {class: 'nowrap'}, Tiny.time(p.time)), Tiny.el('td', {}, p.direction), Tiny.el('td', {}, p.origin),
    Tiny.el('td', {class: 'mono'}, p.hex), Tiny.el('td', {class: 'mono'}, p.decimal), Tiny.el('td', {}, p.note));
}

function matches(p) {
  const node = document.getElementById('node').value.trim();
  const kind = document.getElementById('kind').value;
  const kindOk = !kind || p.direction === kind || (kind === 'REJECTED' && p.note) || (kind === 'GOOD' && !p.note);
  return kindOk && (!node || p.origin === node || p.origin.startsWith(node + ' '));
}

function add(p) {
  if (!live || !matches(p)) return;
  const body = document.getElementById('packets');
  body.prepend(row(p));
  while (body.children.length > MAX_ROWS) body.removeChild(body.lastChild);
}

function query(limit) {
  const p = new URLSearchParams();
  const iso = id => { const v = document.getElementById(id).value; return v ? new Date(v).toISOString() : ''; };
  for (const [key, value] of [['from', iso('from')], ['to', iso('to')], ['origin', document.getElementById('node').value.trim()],
      ['kind', document.getElementById('kind').value], ['limit', limit || document.getElementById('limit').value]]) {
    if (value) p.set(key, value);
  }
  return 'packets?' + p;
}

function show(h, what) {
  const body = Tiny.clear(document.getElementById('packets'));
  for (const p of h.entries.slice().reverse()) body.append(row(p));
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
  try {
    await Tiny.start('packets.html');
    const h = await Tiny.api('GET', 'packets?limit=200');
    show(h, 'Live');
    Tiny.stream('packets', h.entries.length ? h.entries[h.entries.length - 1].seq : -1, add);
  } catch (e) {
    Tiny.fail('packets-box', e);
  }
}
init();
