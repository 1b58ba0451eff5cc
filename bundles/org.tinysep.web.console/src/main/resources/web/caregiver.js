'use strict';
// The caregiver view: is the flat occupied, where and when the last activity was, the inactivity watch, per room.
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
  } else {
    setState('inactivity', c.inactivity.state, c.inactivity.state === 'WATCHING' ? 'watching' : 'not watching');
    detail.textContent = c.inactivity.state === 'WATCHING' ? 'Someone is home; an alert is raised when activity stops for longer than the room\'s limit.'
      : 'Nobody seems to be home: not watching.';
  }
  const body = Tiny.clear(document.getElementById('rooms'));
  for (const r of c.rooms) {
    const a = r.lastActivity;
    body.append(Tiny.el('tr', {}, Tiny.el('td', {}, r.name), Tiny.el('td', {}, r.type),
      Tiny.el('td', {}, a ? Tiny.time(a.time) + ' (' + ago(a.time, c.now) + ')' : 'none in 7 days'),
      Tiny.el('td', {}, a ? a.message + ', ' + a.device : '')));
  }
}

async function init() {
  try {
    await Tiny.start('caregiver.html');
    await refresh();
    setInterval(() => refresh().catch(() => {}), 10000);
  } catch (e) {
    Tiny.fail('caregiver-box', e);
  }
}
init();
