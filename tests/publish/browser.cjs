// What the page tests need around a headless Chromium, with node's own modules only (no npm):
//  - serve(dir): a static HTTP server on a free localhost port, with byte ranges (the browser's
//    media stack seeks through them) and the MIME types the page needs (application/wasm);
//    serve(dir, { ranges: false }) answers as `python3 -m http.server` does (docs/publish.md's
//    server): every file whole (200, no Accept-Ranges), cacheable (Last-Modified);
//  - Browser: Debian's chromium, headless, WebGL2 through SwiftShader, driven over the DevTools
//    protocol on a pipe (--remote-debugging-pipe: JSON messages ended by NUL on fds 3 and 4);
//  - decodePng / diff: the screenshot's and vdfx render's pixels;
//  - pageTest (a test's arguments, checks and exit status), vdfxRunner (vdfx ARGS, checked).
'use strict';
const fs = require('fs');
const http = require('http');
const path = require('path');
const zlib = require('zlib');
const { spawn, spawnSync } = require('child_process');

const MIME = {
  '.html': 'text/html', '.js': 'text/javascript', '.json': 'application/json',
  '.wasm': 'application/wasm', '.mp4': 'video/mp4', '.webm': 'video/webm',
  '.m4v': 'video/mp4', '.frag': 'text/plain', '.vert': 'text/plain',
};

function serve(root, { ranges = true } = {}) {
  const server = http.createServer((req, res) => {
    const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname).replace(/^\/+/, '');
    const file = path.join(root, rel || 'index.html');
    if (!file.startsWith(root) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404);
      res.end();
      return;
    }
    const { size, mtime } = fs.statSync(file);
    const type = MIME[path.extname(file)] || 'application/octet-stream';
    const headers = ranges
      ? { 'Content-Type': type, 'Accept-Ranges': 'bytes', 'Cache-Control': 'no-store' }
      : { 'Content-Type': type, 'Last-Modified': mtime.toUTCString() };
    const m = ranges && /^bytes=(\d*)-(\d*)$/.exec(req.headers.range || '');
    if (m) {
      const start = m[1] ? Number(m[1]) : size - Number(m[2]);
      const end = m[1] && m[2] ? Math.min(Number(m[2]), size - 1) : size - 1;
      res.writeHead(206, { ...headers, 'Content-Range': `bytes ${start}-${end}/${size}`,
                           'Content-Length': end - start + 1 });
      fs.createReadStream(file, { start, end }).pipe(res);
      return;
    }
    res.writeHead(200, { ...headers, 'Content-Length': size });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

class Browser {
  static async launch(profileDir, width, height) {
    const args = ['--headless', '--no-sandbox', '--remote-debugging-pipe',
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      `--user-data-dir=${profileDir}`, `--window-size=${width},${height}`,
      '--force-device-scale-factor=1', '--force-color-profile=srgb', '--hide-scrollbars',
      '--autoplay-policy=no-user-gesture-required', '--mute-audio', '--no-first-run',
      '--disable-background-timer-throttling', '--disable-renderer-backgrounding',
      'about:blank'];
    const proc = spawn(process.env.VDFX_CHROMIUM || 'chromium', args,
                       { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'] });
    const started = new Promise((resolve, reject) => {
      proc.on('spawn', resolve);
      proc.on('error', (e) => reject(new Error(`cannot start ${proc.spawnfile}: ${e.message} ` +
                                                '(install Debian\'s chromium: .ci/deps.sh)')));
    });
    await started;
    const b = new Browser(proc);
    const { targetInfos } = await b.send('Target.getTargets');
    const page = targetInfos.find((t) => t.type === 'page');
    const { sessionId } = await b.send('Target.attachToTarget',
                                       { targetId: page.targetId, flatten: true });
    b.session = sessionId;
    await b.send('Page.enable', {}, sessionId);
    await b.send('Runtime.enable', {}, sessionId);
    return b;
  }

  constructor(proc) {
    this.proc = proc;
    this.next = 1;
    this.pending = new Map();
    this.console = [];
    this.stderr = '';
    proc.stderr.on('data', (d) => { this.stderr += d; });
    let buf = Buffer.alloc(0);
    proc.stdio[4].on('data', (d) => {
      buf = Buffer.concat([buf, d]);
      for (let end; (end = buf.indexOf(0)) >= 0; buf = buf.subarray(end + 1))
        this.#receive(JSON.parse(buf.subarray(0, end).toString('utf8')));
    });
    proc.on('exit', (code) => {
      for (const { reject } of this.pending.values())
        reject(new Error(`chromium exited (${code}): ${this.stderr.slice(-2000)}`));
    });
  }

  #receive(msg) {
    if (msg.id && this.pending.has(msg.id)) {
      const { resolve, reject } = this.pending.get(msg.id);
      this.pending.delete(msg.id);
      if (msg.error) reject(new Error(`${msg.error.message} (${msg.error.code})`));
      else resolve(msg.result);
    } else if (msg.method === 'Runtime.consoleAPICalled') {
      this.console.push(msg.params.args.map((a) => a.value ?? a.description).join(' '));
    } else if (msg.method === 'Runtime.exceptionThrown') {
      this.console.push(msg.params.exceptionDetails.exception?.description ?? 'exception');
    }
  }

  send(method, params = {}, sessionId = this.session) {
    const id = this.next++;
    const msg = { id, method, params };
    if (sessionId) msg.sessionId = sessionId;
    this.proc.stdio[3].write(JSON.stringify(msg) + '\0');
    return new Promise((resolve, reject) => this.pending.set(id, { resolve, reject }));
  }

  async evaluate(expression) {
    const r = await this.send('Runtime.evaluate', { expression, returnByValue: true,
                                                    awaitPromise: true });
    if (r.exceptionDetails) throw new Error(`${expression}: ${r.exceptionDetails.text}`);
    return r.result.value;
  }

  // Opens url and waits for the page's title to say vdfx-ready or vdfx-error; returns it.
  async open(url, width, height, timeoutMs = 30000) {
    this.console = [];
    await this.send('Emulation.setDeviceMetricsOverride',
                    { width, height, deviceScaleFactor: 1, mobile: false });
    await this.send('Page.navigate', { url });
    const t0 = Date.now();
    for (;;) {
      const title = await this.evaluate('document.title').catch(() => '');
      if (title.startsWith('vdfx-ready') || title.startsWith('vdfx-error')) return title;
      if (Date.now() - t0 > timeoutMs)
        throw new Error(`${url}: no vdfx-ready after ${timeoutMs} ms (title "${title}"; ` +
                        `console: ${this.console.join(' | ')})`);
      await new Promise((r) => setTimeout(r, 30));
    }
  }

  async screenshot(width, height) {
    const r = await this.send('Page.captureScreenshot',
      { format: 'png', clip: { x: 0, y: 0, width, height, scale: 1 } });
    return Buffer.from(r.data, 'base64');
  }

  close() {
    this.proc.kill('SIGTERM');
  }
}

// An 8-bit RGB or RGBA PNG (not interlaced) as { width, height, rgb }.
function decodePng(bytes) {
  let off = 8, width = 0, height = 0, type = 0;
  const idat = [];
  while (off < bytes.length) {
    const len = bytes.readUInt32BE(off), kind = bytes.toString('ascii', off + 4, off + 8);
    const data = bytes.subarray(off + 8, off + 8 + len);
    if (kind === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      type = data[9];
      if (data[8] !== 8 || (type !== 2 && type !== 6) || data[12] !== 0)
        throw new Error(`PNG: only 8-bit RGB/RGBA, not interlaced (depth ${data[8]}, type ${type})`);
    } else if (kind === 'IDAT') {
      idat.push(data);
    }
    off += 12 + len;
  }
  const bpp = type === 6 ? 4 : 3, stride = width * bpp;
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const px = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const f = raw[y * (stride + 1)], src = y * (stride + 1) + 1, dst = y * stride;
    for (let i = 0; i < stride; ++i) {
      const a = i >= bpp ? px[dst + i - bpp] : 0, b = y > 0 ? px[dst + i - stride] : 0;
      const c = i >= bpp && y > 0 ? px[dst + i - stride - bpp] : 0;
      const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - 2 * c);
      const pred = [0, a, b, (a + b) >> 1,
                    pa <= pb && pa <= pc ? a : pb <= pc ? b : c][f];
      px[dst + i] = (raw[src + i] + pred) & 255;
    }
  }
  const rgb = Buffer.alloc(width * height * 3);
  for (let k = 0; k < width * height; ++k)
    for (let ch = 0; ch < 3; ++ch) rgb[3 * k + ch] = px[bpp * k + ch];
  return { width, height, rgb };
}

// Largest and mean absolute difference over every channel of two same-size images.
function diff(a, b) {
  if (a.width !== b.width || a.height !== b.height)
    throw new Error(`sizes differ: ${a.width}x${a.height} and ${b.width}x${b.height}`);
  let max = 0, sum = 0;
  for (let i = 0; i < a.rgb.length; ++i) {
    const d = Math.abs(a.rgb[i] - b.rgb[i]);
    if (d > max) max = d;
    sum += d;
  }
  return { max, mean: sum / a.rgb.length };
}

// The frame every page test shares: its arguments as absolute paths (usage and exit 2 when one is
// missing), the last one an output folder made empty, check() counting failures, and run(body),
// which awaits the test and exits 1 on a failure or an exception.
function pageTest(name, argNames) {
  const args = process.argv.slice(2).map((p) => p && path.resolve(p));
  if (args.length < argNames.length || args.slice(0, argNames.length).some((a) => !a)) {
    console.error(`usage: node ${name} ${argNames.join(' ')}`);
    process.exit(2);
  }
  const outDir = args[argNames.length - 1];
  fs.rmSync(outDir, { recursive: true, force: true });
  fs.mkdirSync(outDir, { recursive: true });
  let failures = 0;
  const check = (ok, what) => {
    if (!ok) {
      failures++;
      console.error(`FAIL: ${what}`);
    }
  };
  const run = (title, body) =>
    body().then(() => {
      if (failures) {
        console.error(`${failures} failure(s); images in ${outDir}`);
        process.exit(1);
      }
      console.log(`${title}: all checks passed`);
    }).catch((e) => {
      console.error(e.stack || String(e));
      process.exit(1);
    });
  return { args, check, runTest: run };
}

// `vdfx ARGS` for a test: run(args, { allowFail, cwd, ... }) returns spawnSync's result and
// throws (with vdfx's output) on a non-zero exit unless allowFail.
function vdfxRunner(vdfx) {
  return (args, options = {}) => {
    const r = spawnSync(vdfx, args, { encoding: 'utf8', ...options });
    if (r.status !== 0 && !options.allowFail)
      throw new Error(`vdfx ${args.join(' ')}: exit ${r.status}\n${r.stderr}${r.stdout}`);
    return r;
  };
}

module.exports = { serve, Browser, decodePng, diff, pageTest, vdfxRunner };
