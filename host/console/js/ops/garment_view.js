// host/console/js/ops/garment_view.js: a job's 3D garment (garment.obj, its .mtl and the print packed
// in garment.png) in three.js from libjs-three, orbitable with the mouse and the keyboard.
import * as THREE from "/vendor/three/build/three.module.js";
import { OBJLoader } from "/vendor/three/examples/jsm/loaders/OBJLoader.js";
import { OrbitControls } from "/vendor/three/examples/jsm/controls/OrbitControls.js";
import * as api from "../api.js";

/** The viewer's background; anything else in the canvas is garment. */
export const BACKGROUND = 0x1f252c;

/**
 * Shows job `id`'s garment `objName` (garment.obj or garment-draped.obj) in `host`, sized to it.
 * Sets host.dataset.ready = "1" after the first textured frame, or shows the error and sets "error".
 * Returns a dispose() function that frees the GPU objects.
 */
export async function showGarment(host, id, objName) {
  host.replaceChildren();
  host.dataset.ready = "0";
  const width = Math.max(240, host.clientWidth || 480), height = Math.round(width * 0.8);
  let renderer = null, frame = 0, disposed = false;
  const scene = new THREE.Scene();
  const dispose = () => {
    disposed = true;
    cancelAnimationFrame(frame);
    scene.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) for (const m of [].concat(o.material)) { if (m.map) m.map.dispose(); m.dispose(); }
    });
    if (renderer) renderer.dispose();
  };
  try {
    // WebGL may be unavailable (a browser without GPU or software rendering): said in the panel.
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
    renderer.setSize(width, height);
    renderer.domElement.tabIndex = 0;
    renderer.domElement.setAttribute("aria-label", "3D garment: drag to orbit, wheel to zoom, arrow keys to pan");
    host.appendChild(renderer.domElement);
    scene.background = new THREE.Color(BACKGROUND);
    scene.add(new THREE.AmbientLight(0xffffff, 0.75));
    // The files come through fetch (a bearer token may be needed), the texture named by map_Kd.
    const mtlName = objName.replace(/\.obj$/, ".mtl");
    const [objText, mtlText] = await Promise.all([api.fetchFile(id, objName), api.fetchFile(id, mtlName).catch(() => "")]);
    const mtlLib = (objText.match(/^mtllib\s+(.+)$/m) || [])[1];
    const mtl = mtlLib && mtlLib.trim() !== mtlName ? await api.fetchFile(id, mtlLib.trim()).catch(() => mtlText) : mtlText;
    const mapName = ((mtl.match(/^\s*map_Kd\s+(.+)$/m) || [])[1] || "garment.png").trim();
    const blob = await api.fetchFile(id, mapName, "blob");
    const url = URL.createObjectURL(blob);
    const texture = await new Promise((resolve, reject) =>
      new THREE.TextureLoader().load(url, resolve, undefined, () => reject(new Error(`${mapName}: not an image`))));
    URL.revokeObjectURL(url);
    if (disposed) return dispose;
    const object = new OBJLoader().parse(objText);
    const material = new THREE.MeshLambertMaterial({ map: texture, side: THREE.DoubleSide });
    let meshes = 0;
    object.traverse((o) => { if (o.isMesh) { o.material = material; ++meshes; } });
    if (!meshes) throw new Error(`${objName}: no faces`);
    scene.add(object);
    // Frame the garment: the camera looks at its centre from the front (+z), far enough to see it all.
    const box = new THREE.Box3().setFromObject(object);
    const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
    const span = Math.max(size.x, size.y, size.z);
    const camera = new THREE.PerspectiveCamera(30, width / height, span / 100, span * 20);
    camera.position.copy(centre).add(new THREE.Vector3(0, 0, 1.25 * span / (2 * Math.tan(Math.PI / 12))));
    const sun = new THREE.DirectionalLight(0xffffff, 0.35);
    scene.add(sun);
    sun.position.set(centre.x + span, centre.y + span, centre.z + 2 * span);
    const controls = new OrbitControls(camera, renderer.domElement);
    controls.target.copy(centre);
    controls.update();
    const draw = () => {
      if (disposed) return;
      renderer.render(scene, camera);
      host.dataset.ready = "1";
    };
    controls.addEventListener("change", () => { cancelAnimationFrame(frame); frame = requestAnimationFrame(draw); });
    frame = requestAnimationFrame(draw);
  } catch (e) {
    host.dataset.ready = "error";
    host.replaceChildren(Object.assign(document.createElement("p"), { className: "error", textContent: `3D garment: ${e.message}` }));
    dispose();
  }
  return dispose;
}
