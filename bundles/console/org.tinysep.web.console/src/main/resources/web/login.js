'use strict';
document.getElementById('login').addEventListener('submit', async ev => {
  ev.preventDefault();
  const message = document.getElementById('message');
  message.textContent = '';
  try {
    const r = await fetch('/api/session', {method: 'POST', credentials: 'same-origin',
      headers: {'Content-Type': 'application/json', 'Accept': 'application/json'},
      body: JSON.stringify({user: document.getElementById('user').value,
                            password: document.getElementById('password').value})});
    const data = await r.json().catch(() => ({}));
    if (!r.ok) throw new Error(data.error || ('error ' + r.status));
    location.href = data.role === 'caregiver' ? '/caregiver.html' : '/index.html';
  } catch (e) {
    message.textContent = e.message;
  }
});
