// @ts-check (three.js has no type declarations here: tools/contract/three.d.ts types it as any)
// The 3D view: a surface from GET /surfaces/{id}?format=glb, drawn with three.js, coloured by
// the per-face curvature attributes `_K` / `_H` of the glTF file (three.js names them `_k`, `_h`).

import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/** The view shown now, to be disposed of before the next. @type {{dispose(): void} | null} */
let current = null;

/** @param {ArrayBuffer} buffer @returns {Promise<any>} the parsed glTF */
function parse(buffer) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

// blue (negative) – white (0) – red (positive), symmetric about 0 when the values change sign;
// a constant quantity is drawn in one colour and said so in the legend.
/** @param {number} value @param {number} low @param {number} high */
function colour(value, low, high) {
  const c = new THREE.Color();
  if (!(high > low)) return c.setRGB(0.35, 0.55, 0.85);
  if (low < 0 && high > 0) {
    const m = Math.max(-low, high);
    const t = value / m;
    return t < 0 ? c.setRGB(1 + t * 0.8, 1 + t * 0.6, 1) : c.setRGB(1, 1 - t * 0.7, 1 - t * 0.8);
  }
  const t = (value - low) / (high - low);
  return c.setRGB(0.2 + 0.75 * t, 0.35 + 0.3 * (1 - Math.abs(2 * t - 1)), 0.95 - 0.75 * t);
}

/** @param {any} geometry a three.js BufferGeometry @param {string} name */
function attribute(geometry, name) {
  return geometry.getAttribute(name) || geometry.getAttribute(name.toUpperCase());
}

// What the values say, before colouring them: GLB stores float32 (7 digits), so values within
// a millionth of each other are one value, and values far below the surface's own scale of the
// quantity (1/size for H, 1/size² for K) are zero up to rounding — colouring that noise would
// paint stripes where the service computed 0.
/** @param {number} low @param {number} high @param {string} quantity @param {number} size */
function classify(low, high, quantity, size) {
  const top = Math.max(Math.abs(low), Math.abs(high));
  const unit = quantity === '_k' ? 1 / (size * size) : 1 / size;
  if (top <= 1e-9 * unit) return 'zero';
  if (high - low <= 1e-6 * top) return 'constant';
  return 'varies';
}

/** @param {any[]} meshes three.js meshes @param {string} quantity @param {number} size */
function paint(meshes, quantity, size) {
  let low = Infinity, high = -Infinity, found = false;
  for (const mesh of meshes) {
    const values = attribute(mesh.geometry, quantity);
    if (!values) continue;
    found = true;
    for (let k = 0; k < values.count; k++) { const v = values.getX(k); low = Math.min(low, v); high = Math.max(high, v); }
  }
  const kind = found ? classify(low, high, quantity, size) : 'none';
  for (const mesh of meshes) {
    const geometry = mesh.geometry;
    const values = attribute(geometry, quantity);
    const count = geometry.getAttribute('position').count;
    const colours = new Float32Array(count * 3);
    for (let k = 0; k < count; k++) {
      const c = values && kind === 'varies' ? colour(values.getX(k), low, high)
        : values ? colour(0, 0, 0) : new THREE.Color(0.55, 0.65, 0.8);
      colours.set([c.r, c.g, c.b], 3 * k);
    }
    geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    mesh.material = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide, flatShading: true });
  }
  if (quantity === 'none') return 'Plain colour.';
  if (!found) return `This file carries no ${quantity.toUpperCase().slice(1)} attribute.`;
  const name = quantity === '_k' ? 'K' : 'H';
  const top = Math.max(Math.abs(low), Math.abs(high));
  if (kind === 'zero') return `${name} = 0 on every face, up to rounding (|${name}| ≤ ${top.toExponential(1)}).`;
  if (kind === 'constant') return `${name} = ${((low + high) / 2).toPrecision(6)} on every face.`;
  return `${name} from ${low.toPrecision(4)} (blue) to ${high.toPrecision(4)} (${low < 0 && high > 0 ? 'red; white is 0' : 'red'}).`;
}

/**
 * @param {HTMLElement} container
 * @param {ArrayBuffer} buffer a GLB file (GET /surfaces/{id}?format=glb)
 * @param {string} quantity `_k`, `_h` or `none`
 * @returns {Promise<{triangles: number, legend: string}>}
 */
export async function showSurface(container, buffer, quantity) {
  const gltf = await parse(buffer);
  current?.dispose();
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f6f8);
  /** @type {any[]} */
  const meshes = [];
  gltf.scene.traverse((/** @type {any} */ node) => { if (node.isMesh) meshes.push(node); });
  if (!meshes.length) throw new Error('the file holds no mesh');
  const group = new THREE.Group();
  group.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3()).length() || 1;
  const legend = paint(meshes, quantity, size);
  gltf.scene.position.sub(centre);
  scene.add(group);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
  const light = new THREE.DirectionalLight(0xffffff, 1.5);
  light.position.set(1, 2, 3);
  scene.add(light);

  const width = container.clientWidth || 600, height = container.clientHeight || 400;
  const camera = new THREE.PerspectiveCamera(40, width / height, size / 100, size * 100);
  camera.position.set(0.2 * size, 0.5 * size, 1.2 * size);
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.setSize(width, height, false);
  container.replaceChildren(renderer.domElement);
  renderer.domElement.setAttribute('aria-hidden', 'true');
  const controls = new OrbitControls(camera, renderer.domElement);
  const render = () => {
    renderer.render(scene, camera);
    container.dataset.triangles = String(renderer.info.render.triangles);
    container.dataset.rendered = String(Number(container.dataset.rendered || 0) + 1);
  };
  controls.addEventListener('change', render);

  const step = Math.PI / 18;
  const act = (/** @type {string | undefined} */ what) => {
    if (what === 'left') group.rotation.y -= step;
    else if (what === 'right') group.rotation.y += step;
    else if (what === 'up') group.rotation.x -= step;
    else if (what === 'down') group.rotation.x += step;
    else if (what === 'in') camera.position.multiplyScalar(0.9);
    else if (what === 'out') camera.position.multiplyScalar(1 / 0.9);
    else return false;
    render();
    return true;
  };
  /** @type {Record<string, string>} */
  const keys = { ArrowLeft: 'left', ArrowRight: 'right', ArrowUp: 'up', ArrowDown: 'down', '+': 'in', '=': 'in', '-': 'out' };
  const onKey = (/** @type {KeyboardEvent} */ event) => { if (keys[event.key] && act(keys[event.key])) event.preventDefault(); };
  container.addEventListener('keydown', onKey);
  const buttons = [...document.querySelectorAll('[data-rotate]')];
  const onButton = (/** @type {Event} */ event) => act(/** @type {HTMLElement} */ (event.currentTarget).dataset.rotate);
  for (const b of buttons) b.addEventListener('click', onButton);
  const onResize = () => {
    const w = container.clientWidth || width, h = container.clientHeight || height;
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    renderer.setSize(w, h, false);
    render();
  };
  window.addEventListener('resize', onResize);
  render();
  current = {
    dispose() {
      container.removeEventListener('keydown', onKey);
      for (const b of buttons) b.removeEventListener('click', onButton);
      window.removeEventListener('resize', onResize);
      controls.dispose();
      renderer.dispose();
    },
  };
  container.dataset.legend = legend;
  return { triangles: renderer.info.render.triangles, legend };
}
