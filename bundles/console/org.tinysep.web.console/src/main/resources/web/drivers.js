'use strict';
// Drivers: the drivers list's applications with their state and drivers; upload (install or update), uninstall,
// enable/disable and reload for the installer.
function message(text, ok) {
  const m = document.getElementById('message');
  m.className = ok ? 'ok' : 'error';
  m.textContent = text;
}

async function act(what, call) {
  try {
    const r = await call();
    message(what + (r.changes ? ': ' + (r.changes.join('; ') || 'nothing to change') : '') + (r.note ? ' ' + r.note : ''), true);
  } catch (e) {
    message(what + ' failed: ' + e.message, false);
  }
  await load();
}

function buttons(a) {
  if (Tiny.session.role !== 'installer' || a.symbolicName.startsWith('org.tinysep.web.')) return '';
  const bsn = encodeURIComponent(a.symbolicName);
  const out = [];
  if (a.listed && a.enabled === false) {
    out.push(Tiny.el('button', {type: 'button', class: 'enable', onclick: () => act('Enabled ' + a.symbolicName,
      () => Tiny.api('POST', 'applications/' + bsn + '/enable'))}, 'Enable'));
  } else if (a.listed) {
    out.push(Tiny.el('button', {type: 'button', class: 'disable', onclick: () => act('Disabled ' + a.symbolicName,
      () => Tiny.api('POST', 'applications/' + bsn + '/disable'))}, 'Disable'));
  }
  if (a.bundleId !== null) {
    out.push(Tiny.el('button', {type: 'button', class: 'uninstall', onclick: () => {
      if (confirm('Uninstall ' + a.symbolicName + '? Its devices are removed.')) {
        act('Uninstalled ' + a.symbolicName, () => Tiny.api('DELETE', 'applications/' + bsn));
      }
    }}, 'Uninstall'));
  }
  return out;
}

async function load() {
  const apps = await Tiny.api('GET', 'applications');
  const body = Tiny.clear(document.getElementById('applications'));
  for (const a of apps) {
    body.append(Tiny.el('tr', {'data-bsn': a.symbolicName},
      Tiny.el('td', {}, Tiny.el('b', {}, a.name), Tiny.el('div', {class: 'muted'}, a.symbolicName)),
      Tiny.el('td', {class: 'nowrap'}, a.version),
      Tiny.el('td', {}, Tiny.el('span', {class: 'state state-' + a.state}, a.state), a.uploaded ? Tiny.el('div', {class: 'muted'}, 'uploaded') : null),
      Tiny.el('td', {}, a.listed ? (a.enabled ? 'enabled' : 'disabled') + (a.listStatus ? ' · ' + a.listStatus : '') : 'not listed'),
      Tiny.el('td', {class: 'drivers'}, a.drivers.map(d => Tiny.el('div', {class: 'driver'}, d.name + ' (' + d.devices + ')'))),
      Tiny.el('td', {class: 'nowrap'}, buttons(a))));
  }
  document.getElementById('applications-box').dataset.count = apps.length;
}

async function upload(ev) {
  ev.preventDefault();
  const file = document.getElementById('jar').files[0];
  if (!file) { message('Choose a bundle jar first.', false); return; }
  message('Uploading ' + file.name + '…', true);
  try {
    const r = await fetch('/api/applications', {method: 'POST', credentials: 'same-origin', body: file,
      headers: {'Content-Type': 'application/java-archive', 'X-CSRF-Token': Tiny.session.csrf, 'Accept': 'application/json'}});
    const data = await r.json().catch(() => ({error: 'the platform sent no readable answer (' + r.status + ')'}));
    if (!r.ok) throw new Error(data.error || ('error ' + r.status));
    message(data.application.symbolicName + ' ' + data.application.version + ' ' + data.action
      + (data.note ? '. ' + data.note : ''), true);
    document.getElementById('jar').value = '';
  } catch (e) {
    message('Upload failed: ' + e.message, false);
  }
  await load();
}

async function init() {
  try {
    await Tiny.start('drivers.html');
    if (Tiny.session.role === 'installer') {
      const form = document.getElementById('upload');
      form.hidden = false;
      form.addEventListener('submit', upload);
      document.getElementById('reload').addEventListener('click', () => act('Drivers list reloaded',
        () => Tiny.api('POST', 'applications/reload')));
    }
    await load();
    setInterval(() => load().catch(() => {}), 5000);
  } catch (e) {
    Tiny.fail('applications-box', e);
  }
}
init();
