'use strict';
// The caregiver view: is the flat occupied, where and when the last activity was, the inactivity watch, alerts,
// sensors offline or with a low battery,
// per room its activity over the last 24 h or 7 days (a plot) and its last activity.
function ago(iso, now) {
  const minutes = Math.round((new Date(now) - new Date(iso)) / 60000);
  if (isNaN(minutes)) return '';
  if (minutes < 1) return 'just now';
  if (minutes < 120) return minutes + ' min ago';
  return Math.round(minutes / 60) + ' h ago';
}

function setState(id, state, text) {
  const e = document.getElementById(id);
  e.className = 'big state state-' + state;
  e.textContent = text;
}

async function refresh() {
  const c = await Tiny.api('GET', 'caregiver');
  if (c.occupancy) {
    setState('occupancy', c.occupancy.state, c.occupancy.state === 'OCCUPIED' ? 'occupied'
      : c.occupancy.state === 'UNOCCUPIED' ? 'empty' : 'not known');
    document.getElementById('occupancy-since').textContent = 'since ' + Tiny.time(c.occupancy.since);
  } else {
    setState('occupancy', 'UNKNOWN', 'not known');
    document.getElementById('occupancy-since').textContent = 'Flat Occupancy is not running';
  }
  if (c.lastActivity) {
    document.getElementById('last-activity').textContent = c.lastActivity.room;
    document.getElementById('last-activity-detail').textContent = Tiny.time(c.lastActivity.time) + ' ('
      + ago(c.lastActivity.time, c.now) + '): ' + c.lastActivity.message + ', ' + c.lastActivity.device;
  } else {
    document.getElementById('last-activity').textContent = 'none';
    document.getElementById('last-activity-detail').textContent = 'no movement or door reported by a sensor placed in a room in the last 7 days';
  }
  const detail = Tiny.clear(document.getElementById('inactivity-detail'));
  if (!c.inactivity) {
    setState('inactivity', 'UNKNOWN', 'not running');
  } else if (c.inactivity.state === 'ALERT') {
    setState('inactivity', 'ALERT', 'ALERT');
    const a = c.inactivity.alert;
    if (a) detail.append(Tiny.el('p', {class: 'error'}, 'No activity in ' + a.room + ' since ' + Tiny.time(a.lastActivityAt)
      + ' (' + a.lastActivity + '); help was called at ' + Tiny.time(a.raisedAt) + '.'));
  } else if (c.inactivity.blind) { // every sensor of the watch offline (or none): it cannot see a fall
    setState('inactivity', 'BLIND', 'blind');
    detail.textContent = c.inactivity.sight;
  } else {
    setState('inactivity', c.inactivity.state, c.inactivity.state === 'WATCHING' ? 'watching' : 'not watching');
    detail.textContent = (c.inactivity.state === 'WATCHING' ? 'Someone is home; an alert is raised when activity stops for longer than the room\'s limit.'
      : 'Nobody seems to be home: not watching.') + (c.inactivity.sight ? ' ' + c.inactivity.sight : '');
  }
  // the person nodes: who wears each, when it last reported, its battery, and from Inactivity
  // Recognition's persons(): whether it is worn, its last movement, where its wearer was last seen, the wearer's watch
  const persons = Tiny.clear(document.getElementById('person-nodes'));
  const nodes = c.personNodes || [];
  if (!nodes.length) persons.append(Tiny.el('p', {class: 'muted'}, 'No person node: nobody wears a node (help button, fall detection).'));
  for (const n of nodes) {
    persons.append(Tiny.el('div', {class: 'card person-node', 'data-node': n.node},
      Tiny.el('h3', {}, n.person ? n.person : n.name),
      Tiny.el('div', {class: n.online === false ? 'error' : ''}, (n.lastReport ? Tiny.time(n.lastReport) + ': ' : '') + n.lastReportWords),
      Tiny.el('div', {class: n.batteryLow ? 'warning' : 'muted'}, 'Battery: ' + n.batteryWords),
      Tiny.el('div', {class: 'worn ' + (n.worn === false ? 'warning' : 'muted')}, n.worn === false
        ? 'Seems not worn since ' + Tiny.time(n.lastMovement) + ': ' + n.wornWords : 'Worn: ' + n.wornWords),
      Tiny.el('div', {class: 'last-movement muted'}, 'Last movement: '
        + (n.lastMovement ? Tiny.time(n.lastMovement) + ' (' + n.lastMovementWords + ')' : n.lastMovementWords)),
      Tiny.el('div', {class: 'last-room muted'}, 'Last room: ' + n.lastRoomWords),
      Tiny.el('div', {class: 'person-watch ' + (n.watch === 'ALERT' ? 'error' : 'muted')}, 'Watch: ' + n.watchWords),
      Tiny.el('div', {class: 'muted'}, n.personWords + ' · node ' + n.node)));
  }
  const body = Tiny.clear(document.getElementById('rooms'));
  for (const r of c.rooms) {
    const a = r.lastActivity;
    body.append(Tiny.el('tr', {}, Tiny.el('td', {}, r.name), Tiny.el('td', {}, r.type),
      Tiny.el('td', {}, a ? Tiny.time(a.time) + ' (' + ago(a.time, c.now) + ')' : 'none in 7 days'),
      Tiny.el('td', {}, a ? a.message + ', ' + a.device : '')));
  }
}

// Alerts: the alert service's open alerts with an acknowledge button once that service exists; until then what
// the API says ("no alert service") and Inactivity Recognition's own alert.
async function alerts() {
  const a = await Tiny.api('GET', 'alerts');
  document.getElementById('alert-service').textContent = a.alertService ? 'Open alerts:' : a.message;
  const list = Tiny.clear(document.getElementById('alert-list'));
  for (const alert of a.alerts) {
    const out = Tiny.el('span', {class: 'muted'});
    // what it is about and its explanation in words (a FALL alert: impact, stillness, turn, where last seen)
    list.append(Tiny.el('p', {class: 'error alert', 'data-kind': alert.kind},
      Tiny.el('b', {class: 'alert-kind'}, (alert.kindWords || alert.kind) + ': '), alert.text + ' ', Tiny.el('button', {type: 'button', class: 'acknowledge',
      onclick: async () => {
        try { await Tiny.api('POST', 'alerts/' + encodeURIComponent(alert.id) + '/acknowledge'); await alerts(); }
        catch (e) { out.textContent = e.message; }
      }}, 'Acknowledge'), ' ', out));
    if (alert.explanation && alert.explanation !== alert.text) {
      list.append(Tiny.el('p', {class: 'alert-explanation'}, alert.explanation));
    }
    if (alert.reached && alert.reached.length) { // which channel reached whom
      list.append(Tiny.el('ul', {class: 'muted reached'}, ...alert.reached.map(r => Tiny.el('li', {}, r))));
    }
  }
  const i = a.inactivity;
  if (!i) {
    list.append(Tiny.el('p', {id: 'inactivity-alert'}, 'Inactivity Recognition is not running: nobody watches for a fall.'));
  } else if (i.alert) {
    list.append(Tiny.el('p', {id: 'inactivity-alert', class: 'error'}, 'Inactivity Recognition: no activity in ' + i.alert.room
      + ' since ' + Tiny.time(i.alert.lastActivityAt) + ' (' + i.alert.lastActivity + '); help was called at '
      + Tiny.time(i.alert.raisedAt) + '.'));
  } else {
    list.append(Tiny.el('p', {id: 'inactivity-alert', class: 'ok'}, 'Inactivity Recognition: no alert ('
      + (i.blind ? 'blind' : i.state === 'WATCHING' ? 'watching' : 'not watching: nobody seems to be home') + ').'
      + (i.blind ? ' ' + i.sight : '')));
  }
}

// Sensors (the Sensor Health service, optional): rooms nobody can watch now, each sensor offline and each low
// battery, in plain words ("The Bathroom has no working motion sensor since 14:02: a fall … cannot be noticed").
async function sensors() {
  const s = await Tiny.api('GET', 'caregiver/sensors');
  document.getElementById('sensor-health').textContent = s.message;
  const list = Tiny.clear(document.getElementById('sensor-problems'));
  const line = (cls, x, withSince) => list.append(Tiny.el('li', {class: cls}, x.summary
    + (withSince && x.since ? ' since ' + Tiny.time(x.since) : '') + ': ' + x.meaning + '.'));
  for (const r of s.unmonitored) line('error unmonitored', r, true);
  for (const o of s.offline) line('error offline', o, true);
  for (const b of s.lowBattery) line('warning low-battery', b, false);
}

// The activity timeline: one row per room, one bar per slot (30 min over 24 h, 2 h over 7 days), the bar's height
// the number of movement/door/window reports in that slot, drawn as SVG.
const SVG_NS = 'http://www.w3.org/2000/svg';
function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

function days() {
  return document.querySelector('input[name="days"]:checked').value;
}

async function timeline() {
  const t = await Tiny.api('GET', 'caregiver/timeline?days=' + days());
  const box = Tiny.clear(document.getElementById('timeline'));
  document.getElementById('timeline-range').textContent = Tiny.time(t.from) + ' – ' + Tiny.time(t.to)
    + (t.complete ? '' : ' (the oldest part is missing: too many entries)');
  const slots = t.rooms.length ? t.rooms[0].counts.length : 0;
  const W = 720, LABEL = 130, H = 34, bar = (W - LABEL) / Math.max(1, slots);
  const max = Math.max(1, ...t.rooms.flatMap(r => r.counts));
  const from = new Date(t.from).getTime(), slotMs = t.slotMinutes * 60000;
  const root = svg('svg', {id: 'timeline-svg', width: W, height: H * t.rooms.length + 18, role: 'img',
    'aria-label': 'activity per room, ' + (days() === '1' ? 'last 24 hours' : 'last 7 days')});
  t.rooms.forEach((r, row) => {
    const y = row * H;
    root.append(svg('text', {x: 0, y: y + H / 2 + 4, class: 'room-label'}, r.name.length > 20 ? r.name.substring(0, 19) + '…' : r.name));
    root.append(svg('rect', {x: LABEL, y: y + 4, width: W - LABEL, height: H - 8, class: 'empty'}));
    r.counts.forEach((c, i) => {
      if (!c) return;
      const h = Math.max(2, (H - 8) * c / max);
      const rect = svg('rect', {x: LABEL + i * bar, y: y + H - 4 - h, width: Math.max(1, bar - 1), height: h, class: 'slot'});
      rect.append(svg('title', {}, r.name + ': ' + c + ' activity reports from ' + Tiny.time(new Date(from + i * slotMs).toISOString())));
      root.append(rect);
    });
  });
  const ticks = days() === '1' ? 8 : 7;
  for (let k = 0; k <= ticks; k++) {
    const x = LABEL + k * (W - LABEL) / ticks;
    const at = new Date(from + k * slots * slotMs / ticks);
    root.append(svg('text', {x, y: H * t.rooms.length + 14, 'text-anchor': k === 0 ? 'start' : k === ticks ? 'end' : 'middle'},
      days() === '1' ? at.toLocaleTimeString([], {hour: '2-digit', minute: '2-digit'}) : at.toLocaleDateString([], {weekday: 'short'})));
  }
  box.append(Tiny.el('div', {class: 'timeline'}, root));
  box.dataset.slots = slots;
}

async function init() {
  try {
    await Tiny.start('caregiver.html');
    await refresh();
    await Promise.all([alerts(), sensors(), timeline()]);
    for (const radio of document.querySelectorAll('input[name="days"]')) radio.addEventListener('change', () => timeline().catch(() => {}));
    setInterval(() => Promise.all([refresh(), alerts(), sensors(), timeline()]).catch(() => {}), 10000);
  } catch (e) {
    Tiny.fail('caregiver-box', e);
  }
}
init();
