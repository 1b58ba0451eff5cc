'use strict';
// Devices: every device with its status, room and connections; a settings form for the one chosen
// (#<uid> in the address), generated from its writable parameters, the room as a list of House Information's rooms.
let rooms = [];
let settingsShown = 0;

// Text with a line-break opportunity after each dot between letters or digits: a node address
// (0014.4F01.0000.0102) or a name with one may wrap between its groups, so a narrow column does not force a break
// inside a word (console.css breaks lines between words only).
function dotted(text) {
  return String(text ?? '').split(/(?<=\w\.)(?=\w)/).flatMap((p, i) => i ? [Tiny.el('wbr', {}), p] : [p]);
}

function stateCell(status) {
  return Tiny.el('td', {title: status.detail || ''},
    Tiny.el('span', {class: 'state state-' + status.state}, status.state),
    status.detail ? Tiny.el('div', {class: 'muted'}, status.detail) : null);
}

async function load() {
  const [devices, roomList] = await Promise.all([Tiny.api('GET', 'devices'), Tiny.api('GET', 'rooms').catch(() => [])]);
  rooms = roomList;
  const body = Tiny.clear(document.getElementById('devices'));
  for (const d of devices) {
    body.append(Tiny.el('tr', {'data-uid': d.uid},
      Tiny.el('td', {}, Tiny.el('a', {href: '#' + d.uid, class: 'device-link'}, dotted(d.name))),
      stateCell(d.status), Tiny.el('td', {}, d.type), Tiny.el('td', {}, d.room ? d.room.name : ''),
      Tiny.el('td', {}, dotted(d.nodeAddress)),
      Tiny.el('td', {}, d.connections.map(c => Tiny.el('div', {}, c.interface + ' ← ', dotted(c.providerName || c.providerUid),
        c.vital ? ' (vital)' : ' (optional)')))));
  }
  document.getElementById('devices-box').dataset.count = devices.length;
  await settings();
}

function field(d, p) {
  if (!p.writable) return Tiny.el('span', {}, p.value);
  if (p.key === 'room') {
    const select = Tiny.el('select', {name: 'room', id: 'param-room'}, Tiny.el('option', {value: ''}, '(no room)'));
    for (const r of rooms) {
      select.append(Tiny.el('option', {value: r.uid, selected: d.room && d.room.uid === r.uid}, r.name + ' (' + r.type + ')'));
    }
    return select;
  }
  if (p.options && p.options.length) { // an enumerated parameter: its values as a drop-down
    const select = Tiny.el('select', {name: p.key, id: 'param-' + p.key});
    const values = p.options.includes(p.value) || p.value === '' ? p.options : [p.value, ...p.options];
    if (p.value === '') select.append(Tiny.el('option', {value: ''}, '(not set)'));
    for (const v of values) select.append(Tiny.el('option', {value: v, selected: v === p.value}, v));
    return select;
  }
  return Tiny.el('input', {name: p.key, id: 'param-' + p.key, value: p.value});
}

async function settings() {
  const generation = ++settingsShown; // a form asked for while another is being fetched replaces it
  const box = document.getElementById('settings');
  const uid = decodeURIComponent(location.hash.substring(1));
  if (!uid) { box.hidden = true; return; }
  let d;
  try {
    d = await Tiny.api('GET', 'devices/' + encodeURIComponent(uid));
    if (generation !== settingsShown) return;
  } catch (e) {
    box.hidden = false; Tiny.fail('settings', e); return;
  }
  Tiny.clear(box).hidden = false;
  box.append(Tiny.el('h2', {}, 'Settings of ' + d.name),
    Tiny.el('p', {class: 'muted'}, d.type + ' · ' + d.uid + ' · provides ' + (d.provides.join(', ') || 'nothing')));
  const installer = Tiny.session.role === 'installer';
  const list = Tiny.el('dl', {class: 'params'});
  for (const p of d.parameters) {
    const input = field(d, p);
    const error = Tiny.el('div', {class: 'field-error', id: 'error-' + p.key});
    const dd = Tiny.el('dd', {}, input);
    if (p.writable && installer) {
      dd.append(Tiny.el('button', {type: 'button', id: 'save-' + p.key, onclick: () => save(d.uid, p.key, input, error)}, 'Save'));
    } else if (p.writable) {
      input.disabled = true;
    }
    dd.append(Tiny.el('span', {class: 'muted'}, p.description), error);
    list.append(Tiny.el('dt', {}, p.key), dd);
  }
  box.append(list);
  if (d.functions.length) {
    box.append(Tiny.el('h3', {}, 'Functions'));
    for (const f of d.functions) {
      const out = Tiny.el('span', {class: 'muted'});
      box.append(Tiny.el('p', {}, Tiny.el('button', {type: 'button', disabled: !installer, onclick: async () => {
        try { out.textContent = (await Tiny.api('POST', 'devices/' + encodeURIComponent(d.uid) + '/functions/' + encodeURIComponent(f.name))).result; }
        catch (e) { out.textContent = e.message; }
      }}, f.name), ' ', f.description, ' ', out));
    }
  }
}

async function save(uid, key, input, error) {
  error.textContent = '';
  try {
    const d = await Tiny.api('PUT', 'devices/' + encodeURIComponent(uid) + '/parameters/' + encodeURIComponent(key), {value: input.value});
    await load(); // the list and the form again, as the device now reports them
    const shown = document.getElementById('error-' + key) || error;
    shown.className = 'ok';
    shown.textContent = d.saved === false ? 'saved (not yet in the system backup: the disk did not answer)' : 'saved';
  } catch (e) {
    error.className = 'field-error';
    error.textContent = e.message;
  }
}

async function init() {
  try {
    await Tiny.start('devices.html');
    window.addEventListener('hashchange', settings);
    await load();
  } catch (e) {
    Tiny.fail('devices-box', e);
  }
}
init();
