// the interactive 3-D replay of cairn runs: one view per run side by side, blocks posed per
// sample, one clock for all (play/pause, time slider, time readout), orbit controls per view.
// Data: window.CAIRN_REPLAY = {title, runs: [{label, blocks: [{name, fixed, corners}], t, poses}]}
// (docs/visualisation.md). URL parameters: ?t=SECONDS sets the time and starts paused.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const data = window.CAIRN_REPLAY;
const palette = [0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22];

// triangles of a hexahedron in hex8 corner order (0-3 bottom, 4-7 top), outward winding
const faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]];
const edges = [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [0, 4], [1, 5], [2, 6], [3, 7]];

function hexGeometry(corners) {
  const pos = [];
  for (const f of faces)
    for (const k of [0, 1, 2, 0, 2, 3]) pos.push(...corners[f[k]]);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
  g.computeVertexNormals();
  return g;
}

function hexEdges(corners) {
  const pos = [];
  for (const [a, b] of edges) pos.push(...corners[a], ...corners[b]);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
  return g;
}

// index of the last sample at or before time t
function frameAt(times, t) {
  let lo = 0, hi = times.length - 1;
  if (hi < 0 || t <= times[0]) return 0;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (times[mid] <= t) lo = mid; else hi = mid - 1;
  }
  return lo;
}

// one view: a scene, a camera looking at the blocks, its own orbit controls
function makeView(run, host) {
  const panel = document.createElement('div');
  panel.className = 'view';
  const label = document.createElement('div');
  label.className = 'label';
  label.textContent = run.label;
  panel.appendChild(label);
  const canvas = document.createElement('canvas');
  panel.appendChild(canvas);
  host.appendChild(panel);

  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f4f0);
  // up against gravity (the run's `up`; z when absent): lights and camera placed as for a Z-up
  // scene, turned with it
  const up = run.up ? new THREE.Vector3(run.up[0], run.up[1], run.up[2]).normalize() : new THREE.Vector3(0, 0, 1);
  const turn = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 0, 1), up);
  const sky = new THREE.HemisphereLight(0xffffff, 0x888888, 2.0);
  sky.position.copy(THREE.Object3D.DEFAULT_UP).applyQuaternion(turn);
  scene.add(sky);
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(1, -2, 3).applyQuaternion(turn);
  scene.add(sun);

  // blocks: fixed ones in world coordinates, free ones relative to their centre of mass
  const box = new THREE.Box3();
  const free = [];
  run.blocks.forEach((b, i) => {
    const colour = b.fixed ? 0x9a9a9a : palette[i % palette.length];
    const group = new THREE.Group();
    group.add(new THREE.Mesh(hexGeometry(b.corners), new THREE.MeshStandardMaterial({ color: colour, roughness: 0.8, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 })));
    group.add(new THREE.LineSegments(hexEdges(b.corners), new THREE.LineBasicMaterial({ color: 0x222222 })));
    scene.add(group);
    if (!b.fixed) free.push(group);
  });
  const pose = (k) => {
    const p = run.poses[k] || [];
    free.forEach((g, j) => {
      const o = 7 * j;
      if (o + 7 > p.length) return;
      g.position.set(p[o], p[o + 1], p[o + 2]);
      g.quaternion.set(p[o + 4], p[o + 5], p[o + 6], p[o + 3]);   // x, y, z, w
    });
  };
  pose(0);
  scene.updateMatrixWorld(true);
  box.setFromObject(scene);

  // camera: up against gravity, looking at the blocks from the front-right as a Z-up scene is
  // seen, far enough to see them all
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
  const camera = new THREE.PerspectiveCamera(35, 1, radius / 100, radius * 100);
  camera.up.copy(up);
  camera.position.copy(centre).add(new THREE.Vector3(1.2, -2.4, 1.0).applyQuaternion(turn).multiplyScalar(radius * 1.3));
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(centre);
  controls.update();

  const resize = () => {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
      renderer.setSize(w, h, false);
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
    }
  };
  return {
    end: run.t.length ? run.t[run.t.length - 1] : 0,
    draw(t) {
      resize();
      pose(frameAt(run.t, t));
      controls.update();
      renderer.render(scene, camera);
    },
  };
}

function main() {
  document.title = data.title || 'cairn replay';
  document.getElementById('title').textContent = data.title || '';
  const host = document.getElementById('views');
  const views = data.runs.map((r) => makeView(r, host));
  const end = Math.max(0, ...views.map((v) => v.end));
  const slider = document.getElementById('time');
  const readout = document.getElementById('readout');
  const play = document.getElementById('play');
  slider.max = String(end);
  slider.step = String(end > 0 ? end / 1000 : 1);

  const params = new URLSearchParams(window.location.search);
  let t = params.has('t') ? Math.min(Math.max(parseFloat(params.get('t')) || 0, 0), end) : 0;
  let playing = !params.has('t');
  let last = null;
  const speed = 1.0;   // simulated seconds per wall second

  const show = () => {
    slider.value = String(t);
    readout.textContent = 't = ' + t.toFixed(3) + ' s of ' + end.toFixed(3) + ' s';
    play.textContent = playing ? 'pause' : 'play';
    for (const v of views) v.draw(t);
  };
  play.addEventListener('click', () => {
    playing = !playing;
    if (playing && t >= end) t = 0;
    last = null;
  });
  slider.addEventListener('input', () => {
    t = parseFloat(slider.value);
    playing = false;
  });
  const tick = (now) => {
    if (playing) {
      if (last !== null) t += speed * (now - last) / 1000;
      if (t >= end) { t = end; playing = false; }
    }
    last = now;
    show();
    requestAnimationFrame(tick);
  };
  show();
  document.body.dataset.ready = '1';
  requestAnimationFrame(tick);
}

main();
