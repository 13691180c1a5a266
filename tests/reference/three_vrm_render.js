// Renders every case of /cases.json as three-vrm users see it and posts the pixels back to the
// test's server: GLTFLoader + VRMLoaderPlugin, the file's camera 0 and only the lights GLTFLoader
// made from it (KHR_lights_punctual); sRGB output, no tone mapping, no antialiasing, no shadows.
// A "scene" case is a three.js scene JSON as docs/threejs.md describes it, built here with
// new MToonMaterial({color}) and the scene's lights and camera.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { VRMLoaderPlugin, MToonMaterial } from '@pixiv/three-vrm';

const post = (path, body) => fetch(path, { method: 'POST', body });

function loader() {
  const l = new GLTFLoader();
  l.register((parser) => new VRMLoaderPlugin(parser));
  return l;
}

async function vrmScene(c) {
  const gltf = await loader().loadAsync('/cases/' + c.file);
  // What VRM.update(delta) does for the materials every frame: MToonMaterial.update uploads
  // uniforms it keeps no other way (alphaTest among them) and moves the UV animation (time 0).
  for (const m of gltf.userData.vrmMToonMaterials ?? []) m.update(0);
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  return { scene, camera: gltf.cameras[0] };
}

const colour = (v) => (Array.isArray(v) ? new THREE.Color().fromArray(v) : new THREE.Color(v));

async function jsonScene(c, width, height) {
  const desc = await (await fetch('/cases/' + c.file)).json();
  const gltf = await loader().loadAsync('/cases/' + desc.mesh);
  const material = new MToonMaterial({ color: colour(desc.material.color) });
  material.update(0);
  gltf.scene.traverse((o) => { if (o.isMesh) o.material = material; });
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  for (const l of desc.lights) {
    if (l.type === 'AmbientLight') {
      scene.add(new THREE.AmbientLight(colour(l.color), l.intensity));
    } else {
      const light = new THREE.DirectionalLight(colour(l.color), l.intensity);
      light.position.fromArray(l.position);
      light.target.position.fromArray(l.target);
      scene.add(light, light.target);
    }
  }
  const k = desc.camera;
  const camera = new THREE.PerspectiveCamera(k.fov, width / height, k.near, k.far);
  camera.position.fromArray(k.position);
  camera.lookAt(new THREE.Vector3().fromArray(k.target));
  return { scene, camera };
}

async function renderCase(renderer, c) {
  const [width, height] = c.size;
  renderer.setSize(width, height, false);
  const { scene, camera } = c.kind === 'vrm' ? await vrmScene(c) : await jsonScene(c, width, height);
  renderer.setClearColor(0x000000, 0);
  renderer.clear();
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);  // bottom row first
  await post(`/result?name=${encodeURIComponent(c.name)}&width=${width}&height=${height}`, pixels);
}

async function main() {
  const cases = await (await fetch('/cases.json')).json();
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, alpha: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.toneMapping = THREE.NoToneMapping;
  renderer.shadowMap.enabled = false;
  for (const c of cases) await renderCase(renderer, c);
}

const errors = [];
const log = console.error.bind(console);
console.error = (...args) => { errors.push(args.join(' ')); log(...args); };
main().then(
  () => post('/done', errors.join('\n')),
  (e) => post('/fail', String(e && e.stack ? e.stack : e)));
