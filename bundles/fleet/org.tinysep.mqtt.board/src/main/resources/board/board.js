// TinySEP central alert board: every flat's status, alerts, offline sensors and low batteries, refreshed every
// 3 s. Texts from the flats go into the page through textContent only (el()), never innerHTML.
'use strict';

let csrf = '';

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v === null || v === undefined || v === false) continue;
    if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.substring(2), v);
    else e.setAttribute(k, String(v));
  }
  for (const c of children.flat()) {
    if (c === null || c === undefined) continue;
    e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  }
  return e;
}

async function session() {
  const r = await fetch('/api/session', {credentials: 'same-origin', headers: {'Accept': 'application/json'}});
  if (r.status === 401) { location.href = '/login.html'; return; }
  const s = await r.json();
  csrf = s.csrf || '';
  document.getElementById('who').textContent = 'logged in as ' + s.role;
}

async function acknowledge(flat, id) {
  const by = prompt('Who takes care of it? (your name)', '');
  if (by === null) return;
  const r = await fetch('/board/api/flats/' + encodeURIComponent(flat) + '/alerts/' + encodeURIComponent(id) + '/acknowledge', {
    method: 'POST', credentials: 'same-origin',
    headers: {'Content-Type': 'application/json', 'X-CSRF-Token': csrf, 'Accept': 'application/json'},
    body: JSON.stringify({by})});
  const data = await r.json().catch(() => ({error: 'no readable answer (' + r.status + ')'}));
  document.getElementById('message').textContent = r.ok ? data.explanation : 'Not acknowledged: ' + data.error;
  refresh();
}

function row(f) {
  const alerts = el('td', {});
  for (const a of f.alerts) {
    const item = el('div', {class: 'alert-' + a.state.toLowerCase()}, a.state + ' · ' + (a.kindWords ? a.kindWords + ' · ' : '') + a.explanation);
    if (a.state === 'OPEN') item.append(' ', el('button', {type: 'button', onclick: () => acknowledge(f.flat, a.id)}, 'Acknowledge'));
    alerts.append(item);
  }
  const sensors = el('td', {});
  for (const s of f.offlineSensors) sensors.append(el('div', {}, s.explanation));
  for (const b of f.lowBatteries) sensors.append(el('div', {}, b.explanation));
  if (f.badPayloads > 0) sensors.append(el('div', {class: 'muted'}, f.badPayloads + ' bad messages; last: ' + f.lastBadPayload));
  return el('tr', {class: 'status-' + f.status.toLowerCase()},
    el('td', {}, f.flat), el('td', {}, el('strong', {}, f.status), el('div', {}, f.explanation)),
    el('td', {}, f.occupancy, el('div', {class: 'muted'}, f.occupancyExplanation)), alerts, sensors);
}

async function refresh() {
  const r = await fetch('/board/api/flats', {credentials: 'same-origin', headers: {'Accept': 'application/json'}});
  const data = await r.json().catch(() => ({error: 'no readable answer (' + r.status + ')'}));
  if (!r.ok) { document.getElementById('link').textContent = data.error; return; }
  document.getElementById('link').textContent = 'Broker: ' + data.link;
  const t = data.totals;
  document.getElementById('totals').textContent = t.flats + ' flats, ' + t.messages + ' messages, '
    + t.badPayloads + ' bad, ' + t.duplicates + ' duplicates dropped';
  const body = document.getElementById('flats');
  while (body.firstChild) body.removeChild(body.firstChild);
  for (const f of data.flats) body.append(row(f));
}

session().then(refresh);
setInterval(refresh, 3000);
