// The kiosk's resting view in three.js: the same camera (src/util/math3d.c
// sphere_fit: 30 degree vertical field of view, the model's bounding box
// centred and its farthest vertex on a sphere of radius 1, that sphere
// filling the short side with a margin of 1.08), the same turn (pitch about
// x times yaw about y), the same background, and MeshMatcapMaterial with
// the glTF material's colour, map and vertex colours, as the kiosk's
// base_color = auto does.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const FOV_Y_DEGREES = 30.0;
const FIT_MARGIN = 1.08;

const q = new URLSearchParams(location.search);
const width = parseInt(q.get('w') || '320', 10);
const height = parseInt(q.get('h') || '240', 10);
const yaw = parseFloat(q.get('yaw') || '-30');
const pitch = parseFloat(q.get('pitch') || '20');
const baseColor = (q.get('basecolor') || 'auto') !== 'off';
// [scene] fit's scale of the picture, as the kiosk logged it: three.js's
// camera zoom scales the frustum exactly as the kiosk's clip space.
const zoom = parseFloat(q.get('zoom') || '1');
const out = document.getElementById('out');

function fitDistance(aspect) {
	const halfFov = (FOV_Y_DEGREES / 2) * Math.PI / 180;
	const halfMin = Math.min(halfFov, Math.atan(Math.tan(halfFov) * aspect));
	return FIT_MARGIN / Math.sin(halfMin);
}

// As mesh_fit_positions: the centre of the world-space bounding box and
// the largest distance of a vertex from it.
function fitTransform(root) {
	const box = new THREE.Box3();
	const meshes = [];
	const v = new THREE.Vector3();
	let r2 = 0;

	root.updateMatrixWorld(true);
	root.traverse((o) => { if (o.isMesh) meshes.push(o); });
	// getVertexPosition: as drawn, skinned and morphed.
	for (const m of meshes)
		for (let i = 0; i < m.geometry.attributes.position.count; i++)
			box.expandByPoint(m.getVertexPosition(i, v).applyMatrix4(m.matrixWorld));
	const c = box.getCenter(new THREE.Vector3());
	for (const m of meshes)
		for (let i = 0; i < m.geometry.attributes.position.count; i++)
			r2 = Math.max(r2, m.getVertexPosition(i, v).applyMatrix4(m.matrixWorld).distanceToSquared(c));
	const s = r2 > 0 ? 1 / Math.sqrt(r2) : 1;
	const fit = new THREE.Group();
	fit.scale.setScalar(s);
	fit.position.copy(c).multiplyScalar(-s);
	fit.add(root);
	return fit;
}

// The glTF material's alpha as GLTFLoader reads it (MASK: alphaTest;
// BLEND: transparent, no depth writes), with its colour: as the kiosk,
// alpha comes with the base colour.
// GLTFLoader sets flatShading where a primitive has no NORMAL (the spec
// asks for flat normals there, which the kiosk computes): without it the
// matcap is looked up with a normal of (0,0,0), a corner texel.
function matcapMaterial(m, matcap) {
	const p = { matcap, side: m.side, flatShading: m.flatShading };
	if (baseColor) {
		p.color = m.color;
		p.map = m.map;
		p.vertexColors = m.vertexColors;
		p.opacity = m.opacity;
		p.transparent = m.transparent;
		p.alphaTest = m.alphaTest;
		p.depthWrite = m.depthWrite;
	}
	return new THREE.MeshMatcapMaterial(p);
}

// three.js orders transparent meshes by their origin's depth; the kiosk
// (src/render/draw_list.c), and the glTF spec's advice, by each part's
// bounding box: the farthest part first. The same rule here.
function orderBlended(scene, camera) {
	const v = new THREE.Vector3();
	scene.updateMatrixWorld(true);
	scene.traverse((o) => {
		if (!o.isMesh || !o.material.transparent)
			return;
		o.geometry.computeBoundingBox();
		o.geometry.boundingBox.getCenter(v).applyMatrix4(o.matrixWorld);
		o.renderOrder = -v.distanceTo(camera.position);
	});
}

async function main() {
	const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
	renderer.setPixelRatio(1);
	renderer.setSize(width, height, false);
	renderer.outputColorSpace = THREE.SRGBColorSpace;
	renderer.setClearColor(new THREE.Color().setRGB(0.06, 0.06, 0.07, THREE.SRGBColorSpace));
	document.body.appendChild(renderer.domElement);

	const matcap = await new THREE.TextureLoader().loadAsync(q.get('matcap'));
	matcap.colorSpace = THREE.SRGBColorSpace;
	const gltf = await new GLTFLoader().loadAsync(q.get('model'));
	const root = gltf.scene || gltf.scenes[0];
	root.traverse((o) => {
		if (o.isMesh)
			o.material = Array.isArray(o.material) ? o.material.map((m) => matcapMaterial(m, matcap))
							       : matcapMaterial(o.material, matcap);
	});

	const turn = new THREE.Group();
	const d2r = Math.PI / 180;
	turn.quaternion.multiplyQuaternions(
	    new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(1, 0, 0), pitch * d2r),
	    new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 1, 0), yaw * d2r));
	turn.add(fitTransform(root));
	const scene = new THREE.Scene();
	scene.add(turn);

	const aspect = width / height;
	const dist = fitDistance(aspect);
	const camera = new THREE.PerspectiveCamera(FOV_Y_DEGREES, aspect, dist - 1.5, dist + 1.5);
	camera.position.set(0, 0, dist);
	camera.zoom = zoom;
	camera.updateProjectionMatrix();

	orderBlended(scene, camera);
	renderer.render(scene, camera);
	out.textContent = renderer.domElement.toDataURL('image/png');
}

main().catch((e) => { out.textContent = 'error: ' + e; });
