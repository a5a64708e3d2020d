#!/usr/bin/env node
// render-three.js: renders one frame's .glb (raygl2pov --format gltf) with
// three.js in headless Chromium and writes it as a PNG.
//
//   node render-three.js [--chromium PATH] [--size WxH] [--timeout S] IN.glb OUT.png
//
// A tiny HTTP server on 127.0.0.1 (a port the system picks) serves
// render-three.html, its module and node_modules/three from this folder and
// IN.glb: nothing comes from the network. Chromium runs headless, as root
// too (--no-sandbox), with SwiftShader's software WebGL (no GPU, no
// display), driven over --remote-debugging-pipe (Chrome DevTools Protocol
// on file descriptors 3 and 4, no port). The page renders once with the
// file's camera at extras.imageSize (or --size) and hands back the pixels
// read with gl.readPixels; this script writes them as an 8-bit RGB PNG
// tagged sRGB, as the GL frames of the image tests are. Same file, same
// pixels: no timers, no animation, no antialiasing.
//
// Exit 0 on success, 1 when the file cannot be rendered (the reason on one
// line: "render-three: IN.glb: ..."), 2 on bad usage.
'use strict';
const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');
const zlib = require('zlib');
const {spawn} = require('child_process');

const PROG = 'render-three';
const HERE = __dirname;

function usage(msg) {
    if (msg)
        console.error(`${PROG}: ${msg}`);
    console.error('usage: node render-three.js [--chromium PATH] [--size WxH] [--timeout S] IN.glb OUT.png');
    process.exit(2);
}

function parseArgs(argv) {
    const o = {chromium: '/usr/bin/chromium', width: 0, height: 0, timeout: 120, files: []};
    for (let i = 0; i < argv.length; i++) {
        const a = argv[i];
        const val = () => {
            if (i + 1 >= argv.length)
                usage(`${a} needs a value`);
            return argv[++i];
        };
        if (a === '--chromium') {
            o.chromium = val();
        } else if (a === '--size') {
            const m = /^([1-9][0-9]{0,4})x([1-9][0-9]{0,4})$/.exec(val());
            if (!m)
                usage(`--size ${argv[i]}: WIDTHxHEIGHT, e.g. 400x300`);
            o.width = +m[1];
            o.height = +m[2];
        } else if (a === '--timeout') {
            o.timeout = Number(val());
            if (!(o.timeout > 0))
                usage(`--timeout ${argv[i]}: seconds, more than 0`);
        } else if (a === '-h' || a === '--help') {
            usage();
        } else if (a.startsWith('-') && a !== '-') {
            usage(`unknown option ${a}`);
        } else {
            o.files.push(a);
        }
    }
    if (o.files.length !== 2)
        usage('give one .glb and one .png');
    return o;
}

// ---- PNG ------------------------------------------------------------------------

const CRC_TABLE = (() => {
    const t = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
        let c = n;
        for (let k = 0; k < 8; k++)
            c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
        t[n] = c >>> 0;
    }
    return t;
})();

function crc32(buf) {
    let c = 0xffffffff;
    for (let i = 0; i < buf.length; i++)
        c = CRC_TABLE[(c ^ buf[i]) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
}

function chunk(type, data) {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(data.length, 0);
    head.write(type, 4, 'ascii');
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), data])), 0);
    return Buffer.concat([head, data, crc]);
}

// rgba: rows top first, 4 bytes a pixel; written as RGB (alpha dropped: the
// canvas is opaque) with sRGB and gAMA 1/2.2 chunks.
function encodePng(w, h, rgba) {
    const raw = Buffer.alloc(h * (1 + w * 3));
    for (let y = 0; y < h; y++) {
        const o = y * (1 + w * 3);
        raw[o] = 0; // filter: none
        for (let x = 0; x < w; x++)
            for (let c = 0; c < 3; c++)
                raw[o + 1 + x * 3 + c] = rgba[(y * w + x) * 4 + c];
    }
    const ihdr = Buffer.alloc(13);
    ihdr.writeUInt32BE(w, 0);
    ihdr.writeUInt32BE(h, 4);
    ihdr[8] = 8; // bit depth
    ihdr[9] = 2; // RGB
    const gama = Buffer.alloc(4);
    gama.writeUInt32BE(45455, 0);
    return Buffer.concat([
        Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
        chunk('IHDR', ihdr),
        chunk('sRGB', Buffer.from([0])),
        chunk('gAMA', gama),
        chunk('IDAT', zlib.deflateSync(raw, {level: 6})),
        chunk('IEND', Buffer.alloc(0)),
    ]);
}

// ---- the server ---------------------------------------------------------------------

const TYPES = {'.html': 'text/html', '.js': 'text/javascript', '.json': 'application/json'};

// Serves the page, its module, node_modules/three and the one .glb; nothing
// else (no listing, no path outside those).
function serve(glbBytes) {
    const threeRoot = path.join(HERE, 'node_modules', 'three');
    const server = http.createServer((req, res) => {
        const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
        let file = null, type = null, body = null;
        if (url === '/' || url === '/render-three.html') {
            file = path.join(HERE, 'render-three.html');
        } else if (url === '/render-three-page.js') {
            file = path.join(HERE, 'render-three-page.js');
        } else if (url === '/scene.glb') {
            body = glbBytes;
            type = 'model/gltf-binary';
        } else if (url.startsWith('/node_modules/three/')) {
            const f = path.normalize(path.join(HERE, url));
            if (f.startsWith(threeRoot + path.sep))
                file = f;
        }
        try {
            if (file) {
                body = fs.readFileSync(file);
                type = TYPES[path.extname(file)] || 'application/octet-stream';
            }
        } catch (e) {
            body = null;
        }
        if (!body) {
            res.writeHead(404, {'Content-Type': 'text/plain'});
            res.end('not found');
            return;
        }
        res.writeHead(200, {'Content-Type': type, 'Cache-Control': 'no-store'});
        res.end(body);
    });
    return new Promise((resolve, reject) => {
        server.once('error', reject);
        server.listen(0, '127.0.0.1', () => resolve(server));
    });
}

// ---- Chromium over the DevTools pipe --------------------------------------------------

function startChromium(exe, profile) {
    const args = [
        '--headless', '--no-sandbox', '--remote-debugging-pipe',
        `--user-data-dir=${profile}`,
        // software WebGL: ANGLE on SwiftShader, allowed outside a GPU
        '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
        // nothing of the network or the profile's services
        '--no-first-run', '--no-default-browser-check', '--disable-extensions',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--disable-default-apps', '--no-proxy-server', '--disable-breakpad',
        '--disable-dev-shm-usage', '--mute-audio', '--hide-scrollbars',
        '--force-color-profile=srgb', '--force-device-scale-factor=1',
        'about:blank',
    ];
    // TMPDIR: Chromium's own temporary folders go into the profile, which
    // is removed even when Chromium had to be killed.
    return spawn(exe, args, {stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'],
        env: {...process.env, TMPDIR: profile}});
}

class Cdp {
    constructor(child) {
        this.out = child.stdio[3];
        this.next = 1;
        this.pending = new Map();
        this.waiters = [];
        this.events = [];
        let buf = Buffer.alloc(0);
        // A Chromium that dies closes the pipes: its exit is what is reported.
        this.out.on('error', () => {});
        child.stdio[4].on('error', () => {});
        child.stdio[4].on('data', (d) => {
            buf = Buffer.concat([buf, d]);
            let z;
            while ((z = buf.indexOf(0)) >= 0) {
                const msg = JSON.parse(buf.subarray(0, z).toString('utf8'));
                buf = buf.subarray(z + 1);
                this.dispatch(msg);
            }
        });
    }

    dispatch(msg) {
        if (msg.id !== undefined && this.pending.has(msg.id)) {
            const {resolve, reject, method} = this.pending.get(msg.id);
            this.pending.delete(msg.id);
            if (msg.error)
                reject(new Error(`${method}: ${msg.error.message}`));
            else
                resolve(msg.result);
            return;
        }
        this.events.push(msg);
        this.waiters = this.waiters.filter((w) => !w(msg));
    }

    send(method, params = {}, sessionId = undefined) {
        const id = this.next++;
        const msg = {id, method, params};
        if (sessionId)
            msg.sessionId = sessionId;
        return new Promise((resolve, reject) => {
            this.pending.set(id, {resolve, reject, method});
            this.out.write(JSON.stringify(msg) + '\0');
        });
    }

    // Resolves with the first event named method (already seen or to come).
    event(method, sessionId) {
        const match = (m) => m.method === method && m.sessionId === sessionId;
        const seen = this.events.find(match);
        if (seen)
            return Promise.resolve(seen);
        return new Promise((resolve) => this.waiters.push((m) => match(m) && (resolve(m), true)));
    }
}

async function renderIn(cdp, port, o) {
    const {targetId} = await cdp.send('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await cdp.send('Target.attachToTarget', {targetId, flatten: true});
    await cdp.send('Page.enable', {}, sessionId);
    await cdp.send('Runtime.enable', {}, sessionId);
    const loaded = cdp.event('Page.loadEventFired', sessionId);
    const nav = await cdp.send('Page.navigate', {url: `http://127.0.0.1:${port}/render-three.html`}, sessionId);
    if (nav.errorText)
        throw new Error(`the page did not load: ${nav.errorText}`);
    await loaded;
    const ready = await cdp.send('Runtime.evaluate',
        {expression: 'typeof window.rayglRender', returnByValue: true}, sessionId);
    if (ready.result.value !== 'function')
        throw new Error('the page did not load three.js (tools/node/node_modules/three: run npm ci there)' +
            pageErrors(cdp, sessionId));
    const r = await cdp.send('Runtime.evaluate', {
        expression: `window.rayglRender('/scene.glb', ${o.width}, ${o.height})`,
        awaitPromise: true, returnByValue: true,
    }, sessionId);
    if (r.exceptionDetails) {
        const ex = r.exceptionDetails.exception;
        throw new Error((ex && ex.description ? ex.description.split('\n')[0] : r.exceptionDetails.text) +
            pageErrors(cdp, sessionId));
    }
    return r.result.value;
}

// What the page printed as errors, for a failure's message.
function pageErrors(cdp, sessionId) {
    const lines = [];
    for (const m of cdp.events) {
        if (m.sessionId !== sessionId)
            continue;
        if (m.method === 'Runtime.exceptionThrown')
            lines.push(m.params.exceptionDetails.exception?.description?.split('\n')[0] ||
                m.params.exceptionDetails.text);
        else if (m.method === 'Runtime.consoleAPICalled' && m.params.type === 'error')
            lines.push(m.params.args.map((a) => a.value ?? a.description).join(' '));
    }
    return lines.length ? ` (page: ${lines.slice(0, 3).join('; ')})` : '';
}

async function main() {
    const o = parseArgs(process.argv.slice(2));
    const [inFile, outFile] = o.files;
    const fail = (msg) => {
        console.error(`${PROG}: ${inFile}: ${msg}`);
        process.exitCode = 1;
    };
    let glb;
    try {
        glb = fs.readFileSync(inFile);
    } catch (e) {
        return fail(`cannot read: ${e.message}`);
    }
    if (glb.length < 12 || glb.toString('ascii', 0, 4) !== 'glTF')
        return fail('not a binary glTF file (no "glTF" magic)');
    if (!fs.existsSync(path.join(HERE, 'node_modules', 'three', 'build', 'three.module.js')))
        return fail(`three.js is not installed: run npm ci in ${HERE}`);
    try {
        fs.accessSync(o.chromium, fs.constants.X_OK);
    } catch (e) {
        return fail(`no Chromium at ${o.chromium} (give --chromium PATH)`);
    }

    const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'raygl-three-'));
    let server = null, child = null, cdp = null, timer = null, stderr = '';
    try {
        server = await serve(glb);
        child = startChromium(o.chromium, profile);
        child.stderr.on('data', (d) => {
            stderr = (stderr + d.toString()).slice(-4000);
        });
        const exited = new Promise((_, reject) => child.on('exit', (code, sig) =>
            reject(new Error(`chromium exited (${sig || code}) before the frame was drawn: ` +
                (stderr.trim().split('\n').pop() || 'no message')))));
        const timeout = new Promise((_, reject) => {
            timer = setTimeout(() => reject(new Error(`no picture after ${o.timeout} s (--timeout)`)),
                o.timeout * 1000);
        });
        child.on('error', () => {}); // reported through exit
        cdp = new Cdp(child);
        const res = await Promise.race([renderIn(cdp, server.address().port, o), exited, timeout]);
        const rgba = Buffer.from(res.rgba, 'base64');
        if (rgba.length !== res.width * res.height * 4)
            throw new Error(`the page returned ${rgba.length} bytes for ${res.width}x${res.height}`);
        for (const n of res.notes)
            console.error(`${PROG}: ${inFile}: note: ${n}`);
        const tmp = `${outFile}.tmp-${process.pid}`;
        try {
            fs.writeFileSync(tmp, encodePng(res.width, res.height, rgba));
            fs.renameSync(tmp, outFile);
        } catch (e) {
            fs.rmSync(tmp, {force: true});
            throw new Error(`cannot write ${outFile}: ${e.code || e.message}`);
        }
        if (process.env.RAYGL_THREE_VERBOSE)
            console.error(`${PROG}: three.js r${res.three} on ${res.renderer}: ${outFile} ${res.width}x${res.height}`);
    } catch (e) {
        fail(e.message);
    } finally {
        clearTimeout(timer);
        if (server)
            server.close();
        // Browser.close lets Chromium's helper processes end before the
        // profile folder is removed; SIGKILL after 5 s.
        if (child && child.exitCode === null) {
            const gone = new Promise((r) => child.once('exit', r));
            if (cdp)
                cdp.send('Browser.close').catch(() => {});
            const kill = setTimeout(() => child.kill('SIGKILL'), 5000);
            await gone;
            clearTimeout(kill);
        }
        try {
            fs.rmSync(profile, {recursive: true, force: true, maxRetries: 10, retryDelay: 100});
        } catch (e) {
            console.error(`${PROG}: note: cannot remove ${profile}: ${e.message}`);
        }
    }
}

main();
