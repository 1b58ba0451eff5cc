// TinySEP web console: shared helpers. Every text from the platform goes into the page through textContent
// (el() below), never innerHTML, so a device named <script> is shown as text.
'use strict';

const Tiny = {
  session: null,

  // el('td', {class: 'x'}, 'text', childNode, ...): builds an element; strings become text nodes
  el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (v === null || v === undefined || v === false) continue;
      if (k === 'class') e.className = v;
      else if (k.startsWith('on')) e.addEventListener(k.substring(2), v);
      else e.setAttribute(k, v === true ? '' : String(v));
    }
    for (const c of children.flat()) {
      if (c === null || c === undefined) continue;
      e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    }
    return e;
  },

  clear(node) {
    while (node.firstChild) node.removeChild(node.firstChild);
    return node;
  },

  time(iso) {
    if (!iso) return '';
    const d = new Date(iso);
    return isNaN(d) ? String(iso) : d.toLocaleString();
  },

  shortTime(iso) {
    const d = new Date(iso);
    return isNaN(d) ? String(iso) : d.toLocaleTimeString();
  },

  // fetch wrapper: JSON in and out, the CSRF token on every change; throws Error(message from the API)
  async api(method, path, body) {
    const headers = {'Accept': 'application/json'};
    if (method !== 'GET') {
      headers['X-CSRF-Token'] = Tiny.session ? Tiny.session.csrf : '';
    }
    if (body !== undefined) headers['Content-Type'] = 'application/json';
    const r = await fetch('/api/' + path, {method, headers, credentials: 'same-origin',
      body: body === undefined ? undefined : JSON.stringify(body)});
    if (r.status === 401 && path !== 'session') {
      location.href = '/login.html';
      throw new Error('log in first');
    }
    const data = await r.json().catch(() => ({error: 'the platform sent no readable answer (' + r.status + ')'}));
    if (!r.ok) throw new Error(data.error || ('error ' + r.status));
    return data;
  },

  // the page frame: navigation, who is logged in, the always-visible live event panel
  async start(active) {
    Tiny.session = await Tiny.api('GET', 'session');
    const nav = document.getElementById('nav');
    const pages = [['index.html', 'Event log'], ['devices.html', 'Devices'], ['graph.html', 'Connections'], ['drivers.html', 'Drivers'],
      ['house.html', 'House plan'], ['packets.html', 'Packet log'], ['caregiver.html', 'Caregiver view']];
    for (const [href, label] of pages) {
      nav.append(Tiny.el('a', {href, class: href === active ? 'active' : null}, label));
    }
    const who = Tiny.el('span', {class: 'who', id: 'who'}, 'logged in as ' + Tiny.session.role + ' ');
    who.append(Tiny.el('button', {type: 'button', id: 'logout', onclick: async () => {
      await Tiny.api('DELETE', 'session').catch(() => {});
      location.href = '/login.html';
    }}, 'Log out'));
    nav.append(who);
    Tiny.livePanel();
  },

  // the newest events, live, in the side panel of every page
  livePanel() {
    const list = document.getElementById('live');
    if (!list) return;
    Tiny.api('GET', 'events?limit=30').then(h => {
      for (const e of h.entries) Tiny.prependLive(list, e);
      const last = h.entries.length ? h.entries[h.entries.length - 1].seq : -1;
      Tiny.stream('events', last, e => Tiny.prependLive(list, e));
    }).catch(err => list.append(Tiny.el('li', {class: 'problem'}, err.message)));
  },

  prependLive(list, e) {
    const li = Tiny.el('li', {class: 'kind-' + e.kind, 'data-seq': e.seq},
      Tiny.el('time', {}, Tiny.shortTime(e.time)), ' ', Tiny.el('b', {}, e.originName), ' ', e.message);
    list.prepend(li);
    while (list.children.length > 50) list.removeChild(list.lastChild);
  },

  // Server-Sent Events: one JSON entry per message; reconnects by itself (Last-Event-ID)
  stream(which, after, onEntry) {
    const source = new EventSource('/api/stream/' + which + (after >= 0 ? '?after=' + after : ''));
    source.onmessage = m => { try { onEntry(JSON.parse(m.data)); } catch (e) { console.warn(e); } };
    const status = document.getElementById('live-status');
    source.onopen = () => { if (status) status.textContent = 'live'; };
    source.onerror = () => { if (status) status.textContent = 'reconnecting…'; };
    // the login session ended (logout elsewhere, password change, idle time): the server ended the stream
    source.addEventListener('ended', () => { source.close(); location.href = '/login.html'; });
    return source;
  },

  fail(where, err) {
    const box = document.getElementById(where);
    Tiny.clear(box).append(Tiny.el('p', {class: 'error'}, err.message || String(err)));
  }
};
