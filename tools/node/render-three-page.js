// render-three-page.js: loaded by render-three.html. Defines
// window.rayglRender(url, width, height): loads one .glb with three.js's
// GLTFLoader, renders it once with the file's camera at the frame's pixel
// size (extras.imageSize unless width/height > 0), and resolves to
// {width, height, rgba (base64, rows top first), notes}. Rejects with a
// one-line reason.
//
// Settings are three.js's defaults for a glTF viewer, stated here so a
// later three.js cannot change them silently: output in sRGB, no tone
// mapping, physical light units (r155+: a directional light of intensity
// pi gives the glTF writer's GL diffuse term), no environment light, no
// antialiasing (GL's frames have none).
import * as THREE from 'three';
import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';

function toBase64(bytes) {
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000)
        s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s);
}

async function render(url, width, height) {
    const notes = [];
    const resp = await fetch(url);
    if (!resp.ok)
        throw new Error(`${url}: HTTP ${resp.status}`);
    const gltf = await new GLTFLoader().parseAsync(await resp.arrayBuffer(), '');
    const extras = gltf.parser.json.extras || {};
    const size = Array.isArray(extras.imageSize) ? extras.imageSize : [0, 0];
    const w = width > 0 ? width : size[0], h = height > 0 ? height : size[1];
    if (!(w > 0 && h > 0 && w <= 16384 && h <= 16384))
        throw new Error(`no image size (extras.imageSize ${JSON.stringify(extras.imageSize)}): give --size`);
    const camera = gltf.cameras[0];
    if (!camera)
        throw new Error('the file has no camera');
    if (camera.isPerspectiveCamera && (width > 0 || height > 0)) {
        camera.aspect = w / h;
        camera.updateProjectionMatrix();
    }

    const canvas = document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    const renderer = new THREE.WebGLRenderer({canvas, antialias: false, alpha: false,
        preserveDrawingBuffer: true, powerPreference: 'default'});
    renderer.setPixelRatio(1);
    renderer.setSize(w, h, false);
    renderer.outputColorSpace = THREE.SRGBColorSpace;
    renderer.toneMapping = THREE.NoToneMapping;
    // extras.background and extras.fog hold GL's display values: three.js
    // clears and fogs in the output (sRGB) space, as GL does.
    const bg = Array.isArray(extras.background) ? extras.background : [0, 0, 0, 1];
    renderer.setClearColor(new THREE.Color().setRGB(bg[0], bg[1], bg[2], THREE.SRGBColorSpace), 1);
    // gltf.scene is a Group: fog needs a Scene around it.
    const scene = new THREE.Scene();
    scene.add(gltf.scene);
    const fog = extras.fog;
    if (fog) {
        const fc = new THREE.Color().setRGB(fog.color[0], fog.color[1], fog.color[2], THREE.SRGBColorSpace);
        if (fog.mode === 'linear')
            scene.fog = new THREE.Fog(fc, fog.start, fog.end);
        else if (fog.mode === 'exp2')
            scene.fog = new THREE.FogExp2(fc, fog.density);
        else
            notes.push(`fog mode ${fog.mode}: three.js has none, drawn without fog`);
    }
    scene.updateMatrixWorld(true);
    renderer.render(scene, camera);

    const gl = renderer.getContext();
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const err = gl.getError();
    if (err !== gl.NO_ERROR)
        throw new Error(`WebGL error 0x${err.toString(16)} reading the pixels`);
    // WebGL's rows run bottom first, PNG's top first.
    const rows = new Uint8Array(px.length), stride = w * 4;
    for (let y = 0; y < h; y++)
        rows.set(px.subarray((h - 1 - y) * stride, (h - y) * stride), y * stride);
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const gpu = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    renderer.dispose();
    return {width: w, height: h, rgba: toBase64(rows), notes, renderer: gpu,
        three: THREE.REVISION};
}

window.rayglRender = render;
