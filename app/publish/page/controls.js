// Desktop and phone controls of the player page: drag to look, wheel to zoom the field of
// view, keys (space play/pause, arrows seek 5 s, comma/period one frame, 5 the other eye of a
// stereo video, as in vdfx play), the bar's buttons (play, sound, the seek slider, the eye), and
// device orientation on phones.
const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));
const wrapAz = (az) => ((((az + 180) % 360) + 360) % 360) - 180;

function formatTime(s) {
  const m = Math.floor(s / 60), r = Math.floor(s % 60);
  return `${m}:${String(r).padStart(2, '0')}`;
}

function attachDrag(player) {
  const c = player.canvas;
  let last = null;
  c.addEventListener('pointerdown', (e) => {
    last = [e.clientX, e.clientY];
    c.setPointerCapture(e.pointerId);
    c.classList.add('dragging');
  });
  c.addEventListener('pointermove', (e) => {
    if (!last) return;
    // Degrees per CSS pixel: the horizontal FOV across the canvas's width, so the picture
    // follows the pointer.
    const k = player.view.fov / Math.max(1, c.clientWidth);
    player.view.az = wrapAz(player.view.az - (e.clientX - last[0]) * k);
    player.view.alt = clamp(player.view.alt + (e.clientY - last[1]) * k, -90, 90);
    last = [e.clientX, e.clientY];
    player.dirty = true;
  });
  const end = () => { last = null; c.classList.remove('dragging'); };
  c.addEventListener('pointerup', end);
  c.addEventListener('pointercancel', end);
  c.addEventListener('wheel', (e) => {
    e.preventDefault();
    player.view.fov = clamp(player.view.fov * Math.exp(e.deltaY * 0.001), 20, 120);
    player.dirty = true;
  }, { passive: false });
}

function seekBy(player, seconds) {
  const v = player.video;
  v.currentTime = clamp(v.currentTime + seconds, 0, v.duration || 0);
}

function togglePlay(player) {
  const v = player.video;
  if (v.paused) v.play().catch(() => {});
  else v.pause();
}

function attachKeys(player) {
  window.addEventListener('keydown', (e) => {
    const step = 1 / player.fps();
    const actions = {
      ' ': () => togglePlay(player), ArrowLeft: () => seekBy(player, -5),
      ArrowRight: () => seekBy(player, 5), ',': () => seekBy(player, -step),
      '.': () => seekBy(player, step), 5: () => player.switchEye(),
    };
    if (!actions[e.key]) return;
    e.preventDefault();
    actions[e.key]();
  });
}

function attachBar(player) {
  const v = player.video, play = document.getElementById('play');
  const seek = document.getElementById('seek'), time = document.getElementById('time');
  play.addEventListener('click', () => togglePlay(player));
  const sound = document.getElementById('sound');
  sound.addEventListener('click', () => {
    v.muted = !v.muted;
    sound.textContent = v.muted ? 'Sound on' : 'Sound off';
  });
  v.addEventListener('play', () => { play.textContent = 'Pause'; });
  v.addEventListener('pause', () => { play.textContent = 'Play'; });
  v.addEventListener('timeupdate', () => {
    seek.value = v.duration ? v.currentTime / v.duration : 0;
    time.textContent = `${formatTime(v.currentTime)} / ${formatTime(v.duration || 0)}`;
  });
  seek.addEventListener('input', () => { v.currentTime = seek.value * (v.duration || 0); });
  const eye = document.getElementById('eye');
  eye.hidden = !player.stereo();
  eye.textContent = `${player.eye === 'left' ? 'Left' : 'Right'} eye`;
  eye.addEventListener('click', () => player.switchEye());
}

// Phones: the device's orientation steers the view once it reports one (absolute yaw is
// relative to where the phone pointed at the first reading).
function attachOrientation(player) {
  let yaw0 = null;
  window.addEventListener('deviceorientation', (e) => {
    if (e.alpha === null || e.beta === null) return;
    if (yaw0 === null) yaw0 = e.alpha + player.view.az;
    player.view.az = wrapAz(yaw0 - e.alpha);
    player.view.alt = clamp(e.beta - 90, -90, 90);
    player.dirty = true;
  });
}

export function attachControls(player) {
  attachDrag(player);
  attachKeys(player);
  attachBar(player);
  if (matchMedia('(pointer: coarse)').matches) attachOrientation(player);
}
