// WebXR (immersive-vr): not written yet; the page plays on the desktop and phones only.
export function startXr() {}
