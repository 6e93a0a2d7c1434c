// The kiosk's resting view in three.js: the same camera (src/util/math3d.c
// sphere_fit: 30 degree vertical field of view, the model's bounding box
// centred and its farthest vertex on a sphere of radius 1, that sphere
// filling the short side with a margin of 1.08), the same turn (pitch about
// x times yaw about y), the same background, and MeshMatcapMaterial with
// the glTF material's colour, map and vertex colours, as the kiosk's
// base_color = auto does.
//
// Poses: without `t` the model is drawn as loaded (its nodes' own TRS, the
// default morph weights: the kiosk's still). With `t` (seconds) an
// AnimationMixer plays one clip (`clip`: a name or an index, the first by
// default, as [scene] animation = auto; `all`: every clip at once) looped,
// and mixer.setTime(t) poses it. `fit` picks the bounds the view is fitted to: `pose` (the pose drawn,
// the default without `t`) or `clip` (the whole clip, sampled at its keys
// and at 1/60 of its length: the kiosk keeps the model in frame that way,
// the default with `t`).
//
// What glTF adds to the base colour, as the kiosk draws it: a
// KHR_materials_unlit material (GLTFLoader's MeshBasicMaterial) is kept
// as it is, its colour, map and vertex colours without the matcap;
// emission (emissiveFactor x KHR_materials_emissive_strength x
// emissiveTexture, on its own UV set and transform) is added to the
// matcap's colour in linear light (MeshMatcapMaterial has none: see
// withEmission); `variant` names a KHR_materials_variants variant to draw
// (GLTFLoader reads none: see applyVariant).
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
const shiftX = parseFloat(q.get('sx') || '0');
const shiftY = parseFloat(q.get('sy') || '0');
const time = q.has('t') ? parseFloat(q.get('t')) : null;
const fitMode = q.get('fit') || (time === null ? 'pose' : 'clip');
const variant = q.get('variant');
// How an sRGB map is filtered: `linear` (three.js's own: decoded, then
// filtered, in linear light) or `stored` (the kiosk's on GLES2, which has
// no sRGB textures, and three.js's on WebGL 1 without EXT_sRGB: the stored
// bytes filtered, then decoded). They differ where a magnified texel's
// edge blends two colours (a checker's orange to white: blue 128 against
// 188 at its middle); `stored` shows what is left of a difference
// without it.
const mapFilter = q.get('mapfilter') || 'linear';
const out = document.getElementById('out');

function fitDistance(aspect) {
	const halfFov = (FOV_Y_DEGREES / 2) * Math.PI / 180;
	const halfMin = Math.min(halfFov, Math.atan(Math.tan(halfFov) * aspect));
	return FIT_MARGIN / Math.sin(halfMin);
}

// The world matrices and, for skinned meshes, the bone matrices of the
// pose set now: getVertexPosition reads skeleton.boneMatrices, which only
// skeleton.update() fills (the renderer calls it per frame; before the first
// frame they are zeros and every skinned vertex would read as the origin).
function updatePose(root) {
	root.updateMatrixWorld(true);
	root.traverse((o) => { if (o.isSkinnedMesh) o.skeleton.update(); });
}

// Each vertex in world space as drawn (skinned and morphed) at each pose.
function forEachVertex(root, poses, fn) {
	const meshes = [];
	const v = new THREE.Vector3();

	root.traverse((o) => { if (o.isMesh) meshes.push(o); });
	for (const pose of poses) {
		pose();
		for (const m of meshes)
			for (let i = 0; i < m.geometry.attributes.position.count; i++)
				fn(m.getVertexPosition(i, v).applyMatrix4(m.matrixWorld));
	}
}

// As mesh_fit_positions: the centre of the world-space bounding box and
// the largest distance of a vertex from it, over the given poses.
function fitTransform(root, poses) {
	const box = new THREE.Box3();
	let r2 = 0;

	forEachVertex(root, poses, (p) => box.expandByPoint(p));
	const c = box.getCenter(new THREE.Vector3());
	forEachVertex(root, poses, (p) => { r2 = Math.max(r2, p.distanceToSquared(c)); });
	const s = r2 > 0 ? 1 / Math.sqrt(r2) : 1;
	const fit = new THREE.Group();
	fit.scale.setScalar(s);
	fit.position.copy(c).multiplyScalar(-s);
	fit.add(root);
	return fit;
}

// The clips [scene] animation = auto | NAME | INDEX | all names.
function pickClips(clips, want) {
	if (!clips.length)
		throw new Error('the model has no animation');
	if (want === null || want === '')
		return [clips[0]];
	if (want === 'all')
		return clips;
	const named = clips.find((c) => c.name === want);
	if (named)
		return [named];
	const i = Number(want);
	if (Number.isInteger(i) && i >= 0 && i < clips.length)
		return [clips[i]];
	throw new Error(`no clip "${want}" (the model has ${clips.map((c, k) => c.name || k).join(', ')})`);
}

// The times the whole-clip fit samples: every key of every track, and 60
// steps over the longest clip.
function clipTimes(clips) {
	const times = new Set();
	const duration = Math.max(...clips.map((c) => c.duration));
	for (const clip of clips)
		for (const track of clip.tracks)
			for (const k of track.times)
				times.add(k);
	for (let i = 0; i <= 60; i++)
		times.add((duration * i) / 60);
	return [...times].sort((a, b) => a - b);
}

// The poses to fit to and the one to draw: as loaded, or the clips at t.
function posesOf(gltf, root) {
	const rest = () => updatePose(root);
	if (time === null)
		return { draw: rest, fit: [rest] };
	const clips = pickClips(gltf.animations, q.get('clip'));
	const mixer = new THREE.AnimationMixer(root);
	for (const clip of clips)
		mixer.clipAction(clip).play();
	const at = (t) => () => { mixer.setTime(t); updatePose(root); };
	const fit = fitMode === 'clip' ? clipTimes(clips).map(at) : [at(time)];
	return { draw: at(time), fit };
}

// The glTF material's alpha as GLTFLoader reads it (MASK: alphaTest;
// BLEND: transparent, no depth writes), with its colour: as the kiosk,
// alpha comes with the base colour.
// GLTFLoader sets flatShading where a primitive has no NORMAL (the spec
// asks for flat normals there, which the kiosk computes): without it the
// matcap is looked up with a normal of (0,0,0), a corner texel.
//
// The kiosk's emission (shaders/material.glsl add_emission): the light
// added to the shaded colour in linear light, the sum clamped by the
// framebuffer. MeshMatcapMaterial has no emissive uniforms, but three.js
// sets them for any material that has the properties (WebGLMaterials'
// refreshUniformsCommon) and, for an emissiveMap, defines USE_EMISSIVEMAP
// and its UV (the map's channel: its texCoord) and transform, which
// MeshMatcapMaterial's uv chunks already carry; the fragment shader gets
// the uniforms and the sum.
function withEmission(mat, m) {
	mat.emissive = m.emissive.clone();
	mat.emissiveIntensity = m.emissiveIntensity;
	mat.emissiveMap = m.emissiveMap;
	mat.onBeforeCompile = (shader) => {
		shader.uniforms.emissive = { value: new THREE.Color() };
		shader.uniforms.emissiveMap = { value: null };
		shader.uniforms.emissiveMapTransform = { value: new THREE.Matrix3() };
		shader.fragmentShader = shader.fragmentShader
		    .replace('uniform vec3 diffuse;',
			     'uniform vec3 diffuse;\nuniform vec3 emissive;\n#include <emissivemap_pars_fragment>')
		    .replace('#include <opaque_fragment>',
			     'vec3 totalEmissiveRadiance = emissive;\n#include <emissivemap_fragment>\n' +
				 'outgoingLight += totalEmissiveRadiance;\n#include <opaque_fragment>');
	};
	return mat;
}

function emits(m) {
	return m.emissive !== undefined && m.emissiveIntensity > 0 &&
	       (m.emissive.r > 0 || m.emissive.g > 0 || m.emissive.b > 0);
}

// mapfilter = stored: the maps uploaded as their bytes (no sRGB format)
// and decoded after sampling, through the chunks' own decode for video
// textures (map_fragment's DECODE_VIDEO_TEXTURE, emissivemap_fragment's
// _EMISSIVE): three.js's sRGBTransferEOTF, the kiosk's srgb_to_linear.
function filterStored(mat) {
	if (mapFilter !== 'stored')
		return mat;
	for (const [key, define] of [['map', 'DECODE_VIDEO_TEXTURE'], ['emissiveMap', 'DECODE_VIDEO_TEXTURE_EMISSIVE']]) {
		const t = mat[key];
		if (!t || t.colorSpace !== THREE.SRGBColorSpace)
			continue;
		mat[key] = t.clone();
		mat[key].colorSpace = THREE.NoColorSpace;
		mat.defines = { ...mat.defines, [define]: '' };
	}
	return mat;
}

function matcapMaterial(m, matcap) {
	// Unlit: the base colour as it is (white with base_color = off).
	if (m.isMeshBasicMaterial)
		return filterStored(baseColor ? m.clone() : new THREE.MeshBasicMaterial({ side: m.side }));
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
	const mat = new THREE.MeshMatcapMaterial(p);
	return filterStored(emits(m) ? withEmission(mat, m) : mat);
}

// KHR_materials_variants: each primitive that maps the named variant to a
// material gets it (the others keep their default), as three.js's
// webgl_loader_gltf_variants example does: the material by its index,
// then assignFinalMaterial for the primitive's vertex colours and flat
// shading.
async function applyVariant(gltf, root, name) {
	const json = gltf.parser.json;
	const ext = (json.extensions || {}).KHR_materials_variants;
	const names = ext ? ext.variants.map((v) => v.name) : [];
	const index = names.indexOf(name);
	if (index < 0)
		throw new Error(`no variant "${name}" (the model has ${names.join(', ') || 'none'})`);
	const meshes = [];
	root.traverse((o) => { if (o.isMesh) meshes.push(o); });
	for (const o of meshes) {
		const a = gltf.parser.associations.get(o);
		if (!a || a.meshes === undefined || a.primitives === undefined)
			continue;
		const prim = json.meshes[a.meshes].primitives[a.primitives];
		const mappings = ((prim.extensions || {}).KHR_materials_variants || {}).mappings || [];
		const mapping = mappings.find((mp) => mp.variants.includes(index));
		if (!mapping)
			continue;
		o.material = await gltf.parser.getDependency('material', mapping.material);
		gltf.parser.assignFinalMaterial(o);
	}
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
	if (variant !== null)
		await applyVariant(gltf, root, variant);
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
	const poses = posesOf(gltf, root);
	turn.add(fitTransform(root, poses.fit));
	poses.draw();
	const scene = new THREE.Scene();
	scene.add(turn);

	const aspect = width / height;
	const dist = fitDistance(aspect);
	const camera = new THREE.PerspectiveCamera(FOV_Y_DEGREES, aspect, dist - 1.5, dist + 1.5);
	camera.position.set(0, 0, dist);
	camera.zoom = zoom;
	camera.updateProjectionMatrix();
	// The kiosk's fit centres the model's outline: x += sx w, y += sy w.
	const e = camera.projectionMatrix.elements;
	for (let j = 0; j < 4; j++) {
		e[4 * j] += shiftX * e[4 * j + 3];
		e[4 * j + 1] += shiftY * e[4 * j + 3];
	}
	camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();

	orderBlended(scene, camera);
	renderer.render(scene, camera);
	out.textContent = renderer.domElement.toDataURL('image/png');
}

main().catch((e) => { out.textContent = 'error: ' + e; });
