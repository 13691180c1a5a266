// The reference for VRM spring bones: three-vrm 3.5.5 moves a VRM's spring bones as a three.js
// app does each frame (mixer.update, then vrm.update), with exactly the steps Inkshade takes
// (docs/inputs.md, "Spring bones": 1/60 s from t = 0, the last step ending at the time asked for).
// ANIMATION is one of the file's glTF animations or a VRM animation (a .vrma file), which
// three-vrm-animation 3.5.5 retargets onto the humanoid (createVRMAnimationClip) and vrm.update
// poses (humanoid, look-at, node constraints) before the springs move.
// Prints, for each time, every node's world position as JSON:
//   {"0.5": {"Ponytail1": [x, y, z], ...}, "2": {...}}
// Usage: node tests/reference/spring_bones.mjs FILE.vrm ANIMATION|CLIP.vrma TIME...
import { readFileSync } from 'node:fs';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { VRMHumanoidLoaderPlugin, VRMLoaderPlugin } from '@pixiv/three-vrm';
import { VRMAnimationLoaderPlugin, VRMLookAtQuaternionProxy, createVRMAnimationClip } from '@pixiv/three-vrm-animation';

const [file, animationName, ...times] = process.argv.slice(2);
function arrayBuffer(path) {
  const bytes = readFileSync(path);
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
}
const data = arrayBuffer(file);
const vrma = animationName.toLowerCase().endsWith('.vrma');

// The sample avatar has fewer humanoid bones than VRM 1.0 requires: take those it has. A glTF
// animation drives the file's own nodes, as Inkshade poses them, so the humanoid must not copy
// its normalized bones over them (autoUpdateHumanBones); a .vrma drives the normalized bones,
// which the humanoid copies to the raw ones.
class HumanoidAsItIs extends VRMHumanoidLoaderPlugin {
  _ensureRequiredBonesExist(humanBones) {
    return humanBones;
  }
}

// A fresh load for each time: the joints start from the file's pose (setInitState).
async function load() {
  const loader = new GLTFLoader();
  // Node has no image decoder: textures load as none (spring bones do not look at them).
  loader.register(() => ({ name: 'inkshade_no_textures', loadTexture: () => Promise.resolve(null) }));
  loader.register(
    (parser) =>
      new VRMLoaderPlugin(parser, { humanoidPlugin: new HumanoidAsItIs(parser, { autoUpdateHumanBones: vrma }) }),
  );
  return loader.parseAsync(data, '');
}

// The same steps as Inkshade's spring_step_times.
function stepTimes(time) {
  const h = 1 / 60;
  const out = [];
  if (!(time > 0)) return out;
  const steps = Math.ceil(time / h - 1e-6 / h);
  for (let k = 1; k < steps; ++k) out.push(k * h);
  out.push(time);
  return out;
}

// The .vrma's animation, read once.
async function vrmAnimation() {
  const loader = new GLTFLoader();
  loader.register((parser) => new VRMAnimationLoaderPlugin(parser));
  return (await loader.parseAsync(arrayBuffer(animationName), '')).userData.vrmAnimations[0];
}
const animation = vrma ? await vrmAnimation() : null;

// The clip the mixer plays: the glTF animation, or the .vrma retargeted onto this avatar (with
// a look-at proxy, as three-vrm-animation's examples add one, for its look-at track).
function clipFor(gltf, vrm) {
  if (!vrma) return gltf.animations.find((a) => a.name === animationName);
  if (vrm.lookAt && !vrm.scene.children.some((o) => o instanceof VRMLookAtQuaternionProxy)) {
    const proxy = new VRMLookAtQuaternionProxy(vrm.lookAt);
    proxy.name = 'VRMLookAtQuaternionProxy';
    vrm.scene.add(proxy);
  }
  return createVRMAnimationClip(animation, vrm);
}

// Math.fround: Inkshade's --time is a float.
const result = {};
for (const text of times) {
  const time = Math.fround(Number(text));
  const gltf = await load();
  const vrm = gltf.userData.vrm;
  // three-vrm captures the joints' initial state while loading, before three.js has computed
  // the world matrices of nodes outside the humanoid (a chain under such a node would start
  // from a stale identity matrix and jolt); Inkshade starts the joints in the file's pose, so
  // capture it again with the world matrices computed.
  vrm.scene.updateMatrixWorld(true);
  vrm.springBoneManager.setInitState();
  const mixer = new THREE.AnimationMixer(vrm.scene);
  const clip = clipFor(gltf, vrm);
  if (clip) {
    const action = mixer.clipAction(clip);
    action.setLoop(THREE.LoopOnce, 1);
    action.clampWhenFinished = true;
    action.play();
  }
  let before = 0;
  for (const t of stepTimes(time)) {
    mixer.update(t - before);
    vrm.update(t - before);
    before = t;
  }
  vrm.scene.updateMatrixWorld(true);
  const positions = {};
  for (const node of await gltf.parser.getDependencies('node')) {
    const p = new THREE.Vector3().setFromMatrixPosition(node.matrixWorld);
    positions[node.name] = [p.x, p.y, p.z];
  }
  result[text] = positions;
}
console.log(JSON.stringify(result));
