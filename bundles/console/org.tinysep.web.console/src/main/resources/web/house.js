'use strict';
// House plan: House Information's rooms with name, type and neighbour links (thesis Fig 3.7), editable by the
// installer; a drawing of the plan above it (rooms on an ellipse, a line per link).
const SVG_NS = 'http://www.w3.org/2000/svg';
const TYPES = ['Bathroom', 'Bedroom', 'Hall', 'Kitchen', 'Living room', 'Study'];

function message(text, ok) {
  const m = document.getElementById('message');
  m.className = ok ? 'ok' : 'error';
  m.textContent = text;
}

async function change(what, call, error) {
  try {
    await call();
    message(what, true);
    await load();
  } catch (e) {
    if (error) { error.textContent = e.message; } else { message(e.message, false); }
  }
}

function row(r, rooms, installer) {
  const uid = encodeURIComponent(r.uid);
  const name = Tiny.el('input', {class: 'room-name', value: r.name, maxlength: 100, disabled: !installer});
  const type = Tiny.el('input', {class: 'room-type', value: r.type, list: 'room-types', maxlength: 100, disabled: !installer});
  const error = Tiny.el('div', {class: 'field-error'});
  const links = rooms.filter(o => o.uid !== r.uid).map(o => {
    const box = Tiny.el('input', {type: 'checkbox', class: 'link', 'data-other': o.uid, checked: r.neighbours.includes(o.uid), disabled: !installer,
      onchange: () => change((box.checked ? 'Linked ' : 'Unlinked ') + r.name + ' and ' + o.name,
        () => Tiny.api(box.checked ? 'PUT' : 'DELETE', 'rooms/' + uid + '/neighbours/' + encodeURIComponent(o.uid)), error)});
    return Tiny.el('label', {class: 'inline'}, box, o.name);
  });
  const actions = installer ? [
    Tiny.el('button', {type: 'button', class: 'save', onclick: () => change('Saved ' + name.value,
      () => Tiny.api('PUT', 'rooms/' + uid, {name: name.value, type: type.value}), error)}, 'Save'),
    Tiny.el('button', {type: 'button', class: 'delete', onclick: () => change('Removed ' + r.name,
      () => Tiny.api('DELETE', 'rooms/' + uid), error)}, 'Remove')] : [];
  return Tiny.el('tr', {'data-uid': r.uid}, Tiny.el('td', {}, name, error), Tiny.el('td', {}, type),
    Tiny.el('td', {class: 'links'}, links.length ? links : Tiny.el('span', {class: 'muted'}, 'no other room')),
    Tiny.el('td', {class: 'nowrap'}, actions));
}

function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

function plan(rooms) {
  const W = 720, H = rooms.length > 2 ? 250 : 60, rx = rooms.length > 1 ? 290 : 0, ry = rooms.length > 2 ? 95 : 0;
  const pos = new Map(rooms.map((r, i) => [r.uid, {
    x: W / 2 + rx * Math.cos(2 * Math.PI * i / rooms.length - Math.PI / 2),
    y: H / 2 + ry * Math.sin(2 * Math.PI * i / rooms.length - Math.PI / 2)}]));
  const root = svg('svg', {id: 'plan-svg', width: W, height: H, viewBox: '0 0 ' + W + ' ' + H, role: 'img',
    'aria-label': rooms.length + ' rooms and their links'});
  for (const r of rooms) {
    for (const n of r.neighbours) {
      if (r.uid < n && pos.has(n)) {
        const a = pos.get(r.uid), b = pos.get(n);
        root.append(svg('line', {x1: a.x, y1: a.y, x2: b.x, y2: b.y, class: 'link-line'}));
      }
    }
  }
  for (const r of rooms) {
    const p = pos.get(r.uid);
    const g = svg('g', {class: 'room'});
    g.append(svg('rect', {x: p.x - 60, y: p.y - 20, width: 120, height: 40, rx: 6}));
    g.append(svg('text', {x: p.x, y: p.y - 3, 'text-anchor': 'middle'}, r.name.length > 18 ? r.name.substring(0, 17) + '…' : r.name));
    g.append(svg('text', {x: p.x, y: p.y + 13, 'text-anchor': 'middle', class: 'sub'}, r.type));
    g.append(svg('title', {}, r.name + ' (' + r.type + ')'));
    root.append(g);
  }
  Tiny.clear(document.getElementById('plan')).append(root);
}

async function load() {
  const rooms = await Tiny.api('GET', 'rooms');
  const installer = Tiny.session.role === 'installer';
  const body = Tiny.clear(document.getElementById('rooms'));
  for (const r of rooms) body.append(row(r, rooms, installer));
  if (!rooms.length) body.append(Tiny.el('tr', {}, Tiny.el('td', {colspan: 4, class: 'muted'}, 'No rooms yet.')));
  const types = Tiny.clear(document.getElementById('room-types'));
  for (const t of [...new Set([...TYPES, ...rooms.map(r => r.type)])].sort()) types.append(Tiny.el('option', {value: t}));
  plan(rooms);
  document.getElementById('house-box').dataset.count = rooms.length;
}

async function init() {
  try {
    await Tiny.start('house.html');
    if (Tiny.session.role === 'installer') {
      const form = document.getElementById('add-room');
      form.hidden = false;
      form.addEventListener('submit', ev => {
        ev.preventDefault();
        const name = document.getElementById('new-name'), type = document.getElementById('new-type');
        change('Added ' + name.value, async () => {
          await Tiny.api('POST', 'rooms', {name: name.value, type: type.value});
          name.value = ''; type.value = '';
        });
      });
    }
    await load();
  } catch (e) {
    Tiny.fail('house-box', e);
  }
}
init();
