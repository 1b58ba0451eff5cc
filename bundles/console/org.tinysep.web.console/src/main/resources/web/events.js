'use strict';
// The event log page: the newest entries, live (Server-Sent Events), a filter on what is shown, and a search of
// the log's history (time range, device, kind, limit).
const KINDS = ['DRIVER_ADDED', 'DRIVER_REMOVED', 'DEVICE_CREATED', 'DEVICE_REMOVED', 'CONNECTED', 'DISCONNECTED',
  'DEVICE_EVENT', 'STATUS', 'PROBLEM'];
const MAX_ROWS = 1000;
let live = true;

function row(e) {
  return Tiny.el('tr', {class: 'kind-' + e.kind, 'data-seq': e.seq},
    Tiny.el('td', {class: 'nowrap'}, Tiny.time(e.time)), Tiny.el('td', {class: 'nowrap'}, e.kind),
    Tiny.el('td', {title: e.origin}, e.originName), Tiny.el('td', {}, e.message));
}

function visible(tr) {
  const text = document.getElementById('filter').value.toLowerCase();
  const kind = document.getElementById('kind').value;
  return (!text || tr.textContent.toLowerCase().includes(text)) && (!kind || tr.classList.contains('kind-' + kind));
}

function applyFilter() {
  for (const tr of document.getElementById('events').children) tr.hidden = !visible(tr);
}

function add(e) {
  if (!live) return;
  const body = document.getElementById('events');
  const tr = row(e);
  tr.hidden = !visible(tr);
  body.prepend(tr);
  while (body.children.length > MAX_ROWS) body.removeChild(body.lastChild);
}

function show(history, what) {
  const body = Tiny.clear(document.getElementById('events'));
  for (const e of history.entries.slice().reverse()) body.append(row(e));
  applyFilter();
  document.getElementById('summary').textContent = what + ': ' + history.entries.length + ' of '
    + history.matched + ' matching entries' + (history.damagedLines ? ' (' + history.damagedLines + ' damaged lines skipped)' : '');
}

function isoOf(id) {
  const v = document.getElementById(id).value;
  return v ? new Date(v).toISOString() : '';
}

async function search(ev) {
  ev.preventDefault();
  const p = new URLSearchParams();
  for (const [key, value] of [['from', isoOf('from')], ['to', isoOf('to')],
      ['origin', document.getElementById('device').value.trim()], ['kind', document.getElementById('kind').value],
      ['limit', document.getElementById('limit').value]]) {
    if (value) p.set(key, value);
  }
  try {
    const h = await Tiny.api('GET', 'events?' + p);
    live = false;
    show(h, 'History');
  } catch (e) {
    document.getElementById('summary').textContent = e.message;
  }
}

async function init() {
  const kind = document.getElementById('kind');
  for (const k of KINDS) kind.append(Tiny.el('option', {value: k}, k));
  document.getElementById('filter').addEventListener('input', applyFilter);
  kind.addEventListener('change', applyFilter);
  document.getElementById('search').addEventListener('submit', search);
  document.getElementById('live-mode').addEventListener('click', () => location.reload());
  try {
    await Tiny.start('index.html');
    const h = await Tiny.api('GET', 'events?limit=200');
    show(h, 'Live');
    performance.mark('events-shown'); // the browser test measures the time to the first rows
    document.getElementById('summary').textContent = 'Live: newest entries first; new ones appear as they happen.';
    Tiny.stream('events', h.entries.length ? h.entries[h.entries.length - 1].seq : -1, add);
  } catch (e) {
    Tiny.fail('events-box', e);
  }
}
init();
