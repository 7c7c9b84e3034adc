// host/console/studio/studio_scene.js: the studio's 3D garment (three.js r111 from libjs-three):
// the daemon's preview atlas mapped through the mesh's per-piece UVs, orbit, and the tools that
// work on the surface by raycasting (place a planar image, paint a stroke), with the layers'
// guides drawn over it (cylinder axis, planar frame, stroke paths).

const BACKGROUND = 0x1f252c;

/** Loads three.js and its OBJLoader/OrbitControls modules from `base` (ends with "/"). */
export async function loadThree(base) {
  const [THREE, obj, orbit] = await Promise.all([
    import(`${base}build/three.module.js`),
    import(`${base}examples/jsm/loaders/OBJLoader.js`),
    import(`${base}examples/jsm/controls/OrbitControls.js`),
  ]);
  return { THREE, OBJLoader: obj.OBJLoader, OrbitControls: orbit.OrbitControls };
}

/**
 * The view in `host`. `handlers`: onPlace(hit, phase) for the Place tool ("down", "move", "up"),
 * onPaint(hit, phase) for the Paint tool; a hit is {point:[x,y,z] mm, normal:[x,y,z], piece};
 * onHandle("size" | "rotation", steps) from the wheel in the Place tool and the [ ] , . keys.
 */
export function createScene(lib, host, handlers) {
  const { THREE, OBJLoader, OrbitControls } = lib;
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.domElement.tabIndex = 0;
  renderer.domElement.className = "st-canvas";
  renderer.domElement.setAttribute("aria-label",
    "3D garment: Orbit tool drags to turn and arrow keys pan; Place tool clicks to put an image; Paint tool drags to paint");
  host.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(BACKGROUND);
  scene.add(new THREE.AmbientLight(0xffffff, 0.8));
  const sun = new THREE.DirectionalLight(0xffffff, 0.3);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(30, 1, 1, 100000);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableKeys = true;
  controls.keys = { LEFT: 37, UP: 38, RIGHT: 39, BOTTOM: 40 };
  controls.listenToKeyEvents && controls.listenToKeyEvents(renderer.domElement);
  const guides = new THREE.Group();
  scene.add(guides);
  const material = new THREE.MeshLambertMaterial({ color: 0xffffff, side: THREE.DoubleSide });
  let garment = null, tool = "orbit", frame = 0, dragging = false, span = 1000;
  const raycaster = new THREE.Raycaster();

  const draw = () => { cancelAnimationFrame(frame); frame = requestAnimationFrame(() => renderer.render(scene, camera)); };
  controls.addEventListener("change", draw);

  function resize() {
    const w = Math.max(320, host.clientWidth), h = Math.max(240, host.clientHeight);
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    draw();
  }
  new ResizeObserver(resize).observe(host);

  /** Replaces the garment with the OBJ text (positions in mm, UVs into the atlas). */
  function load(objText) {
    if (garment) { scene.remove(garment); garment.traverse((o) => o.geometry && o.geometry.dispose()); }
    garment = new OBJLoader().parse(objText);
    garment.traverse((o) => { if (o.isMesh) o.material = material; });
    scene.add(garment);
    const box = new THREE.Box3().setFromObject(garment);
    const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
    span = Math.max(size.x, size.y, size.z);
    camera.near = span / 100;
    camera.far = span * 20;
    camera.position.copy(centre).add(new THREE.Vector3(0, 0, 1.2 * span / (2 * Math.tan(Math.PI / 12))));
    camera.updateProjectionMatrix();
    sun.position.set(centre.x + span, centre.y + span, centre.z + 2 * span);
    controls.target.copy(centre);
    controls.update();
    resize();
    return { centre: centre.toArray(), size: size.toArray() };
  }

  /** Maps the atlas image (a Blob); resolves once a frame with it has been drawn. */
  async function setAtlas(blob) {
    const url = URL.createObjectURL(blob);
    const texture = await new Promise((resolve, reject) =>
      new THREE.TextureLoader().load(url, resolve, undefined, () => reject(new Error("preview atlas is not an image"))));
    URL.revokeObjectURL(url);
    texture.anisotropy = renderer.capabilities.getMaxAnisotropy();
    const old = material.map;
    material.map = texture;
    material.needsUpdate = true;
    if (old) old.dispose();
    cancelAnimationFrame(frame);
    renderer.render(scene, camera);
    await new Promise((r) => requestAnimationFrame(() => r()));
  }

  /** The garment surface under client point (x, y), or null. */
  function pick(x, y) {
    if (!garment) return null;
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((x - rect.left) / rect.width) * 2 - 1, -((y - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    const hits = raycaster.intersectObject(garment, true);
    if (!hits.length) return null;
    const h = hits[0];
    const n = h.face.normal.clone().transformDirection(h.object.matrixWorld);
    if (n.dot(raycaster.ray.direction) > 0) n.negate();  // the side the designer looks at
    return { point: h.point.toArray(), normal: n.toArray(), piece: h.object.name };
  }

  /** Client coordinates of a garment point (mm), for tests and guides. */
  function screenOf(p) {
    const v = new THREE.Vector3(...p).project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return { x: rect.left + (v.x + 1) / 2 * rect.width, y: rect.top + (1 - v.y) / 2 * rect.height };
  }

  function setTool(name) {
    tool = name;
    controls.enabled = name === "orbit";
    renderer.domElement.style.cursor = name === "orbit" ? "grab" : "crosshair";
  }

  const canvas = renderer.domElement;
  canvas.addEventListener("pointerdown", (e) => {
    if (tool === "orbit" || e.button !== 0) return;
    const hit = pick(e.clientX, e.clientY);
    if (!hit) return;
    dragging = true;
    canvas.setPointerCapture && canvas.setPointerCapture(e.pointerId);
    (tool === "place" ? handlers.onPlace : handlers.onPaint)(hit, "down");
    e.preventDefault();
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!dragging) return;
    const hit = pick(e.clientX, e.clientY);
    if (hit) (tool === "place" ? handlers.onPlace : handlers.onPaint)(hit, "move");
  });
  const end = (e) => {
    if (!dragging) return;
    dragging = false;
    (tool === "place" ? handlers.onPlace : handlers.onPaint)(pick(e.clientX, e.clientY), "up");
  };
  canvas.addEventListener("pointerup", end);
  canvas.addEventListener("wheel", (e) => {
    if (tool !== "place" || !handlers.onHandle) return;
    e.preventDefault();
    handlers.onHandle(e.shiftKey ? "rotation" : "size", e.deltaY < 0 ? 1 : -1);
  }, { passive: false });
  canvas.addEventListener("keydown", (e) => {
    if (!handlers.onHandle) return;
    const k = { "[": ["size", -1], "]": ["size", 1], ",": ["rotation", -1], ".": ["rotation", 1] }[e.key];
    if (k) { e.preventDefault(); handlers.onHandle(k[0], k[1]); }
  });
  canvas.addEventListener("pointercancel", end);

  /** Draws the guides of `layers` (the selected one brighter). `axisGuess` = {centre, size}. */
  function setGuides(layers, selectedId, axisGuess) {
    for (const c of [...guides.children]) { guides.remove(c); c.geometry.dispose(); c.material.dispose(); }
    const line = (points, colour, closed) => {
      const g = new THREE.BufferGeometry().setFromPoints(points.map((p) => new THREE.Vector3(...p)));
      const m = new THREE.LineBasicMaterial({ color: colour, depthTest: false, transparent: true, opacity: 0.9 });
      const l = closed ? new THREE.LineLoop(g, m) : new THREE.Line(g, m);
      l.renderOrder = 10;
      guides.add(l);
    };
    for (const layer of layers) {
      if (layer.hidden) continue;
      const colour = layer.id === selectedId ? 0xffd400 : 0x7fa8c8;
      if (layer.type === "cylindrical" && axisGuess) {
        const o = layer.custom_axis ? layer.axis_origin.map(Number) : [axisGuess.centre[0], axisGuess.centre[1], axisGuess.centre[2]];
        const d = layer.custom_axis ? layer.axis_direction.map(Number) : [0, 1, 0];
        const len = Math.hypot(...d) || 1, half = axisGuess.size[1] * 0.7;
        line([o.map((x, i) => x - d[i] / len * half), o.map((x, i) => x + d[i] / len * half)], colour);
      } else if (layer.type === "planar" && layer.centre && layer.up) {
        const n = layer.normal, u = layer.up, c = layer.centre;
        const r = [u[1] * n[2] - u[2] * n[1], u[2] * n[0] - u[0] * n[2], u[0] * n[1] - u[1] * n[0]];
        const w = Number(layer.width) / 2, h = (Number(layer.height) || Number(layer.width)) / 2;
        const at = (a, b) => c.map((x, i) => x + a * r[i] + b * u[i] + 2 * n[i]);
        line([at(-w, -h), at(w, -h), at(w, h), at(-w, h)], colour, true);
        line([at(0, 0), at(0, h * 1.3)], colour);
      } else if (layer.type === "stroke" && layer.points.length > 1) {
        if (layer.id === selectedId) line(layer.points, colour);
      }
    }
    draw();
  }

  return { load, setAtlas, pick, screenOf, setTool, setGuides, draw, canvas, span: () => span };
}
