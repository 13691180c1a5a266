// The pose three-vrm 3.5.5 gives a VRM avatar, for the retargeting tests
// (tests/io/vrm_animation_reference_test.cpp): loads AVATAR (.vrm) and optionally a VRM
// animation (.vrma, or "-" for none), and for each time T plays the clip with an
// AnimationMixer at T, sets the expressions given (NAME=W, after the clip as a user would),
// runs vrm.update(0) (humanoid, look-at, expressions, node constraints) and prints one JSON line:
// every glTF node's world position and morph weights, in node order.
//
//   node vrm_pose.mjs AVATAR.vrm CLIP.vrma|- T[,T...] [NAME=W ...]
import fs from 'node:fs';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { VRMLoaderPlugin } from '@pixiv/three-vrm';
import { VRMAnimationLoaderPlugin, VRMLookAtQuaternionProxy, createVRMAnimationClip } from '@pixiv/three-vrm-animation';

function parse(path, plugin) {
  const bytes = fs.readFileSync(path);
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const loader = new GLTFLoader();
  loader.register(plugin);
  return new Promise((resolve, reject) => loader.parse(buffer, '', resolve, reject));
}

const [avatarPath, clipPath, timesText, ...expressionArgs] = process.argv.slice(2);
const poses = [];
for (const time of timesText.split(',').map(Number)) {
  // A fresh avatar for each time: one frame from the loaded state, as Inkshade poses it.
  const gltf = await parse(avatarPath, (parser) => new VRMLoaderPlugin(parser));
  const vrm = gltf.userData.vrm;
  const nodes = await gltf.parser.getDependencies('node');
  if (clipPath !== '-') {
    const animationGltf = await parse(clipPath, (parser) => new VRMAnimationLoaderPlugin(parser));
    if (!vrm.scene.children.some((o) => o instanceof VRMLookAtQuaternionProxy) && vrm.lookAt) {
      const proxy = new VRMLookAtQuaternionProxy(vrm.lookAt);
      proxy.name = 'VRMLookAtQuaternionProxy';
      vrm.scene.add(proxy);
    }
    const clip = createVRMAnimationClip(animationGltf.userData.vrmAnimations[0], vrm);
    const mixer = new THREE.AnimationMixer(vrm.scene);
    mixer.clipAction(clip).play();
    mixer.setTime(time);
  }
  for (const arg of expressionArgs) {
    const [name, weight] = arg.split('=');
    vrm.expressionManager.setValue(name, Number(weight));
  }
  vrm.update(0);
  vrm.scene.updateMatrixWorld(true);
  poses.push({
    time,
    nodes: nodes.map((node) => ({
      name: node.name,
      position: node.getWorldPosition(new THREE.Vector3()).toArray(),
      weights: node.morphTargetInfluences ? Array.from(node.morphTargetInfluences) : [],
    })),
  });
}
process.stdout.write(JSON.stringify(poses) + '\n');
