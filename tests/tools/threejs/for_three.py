#!/usr/bin/env python3
"""The copy of a glTF model that three.js's page loads (compare.sh):

    for_three.py IN OUT

- extensionsUsed lists every extension the file uses. The spec requires
  it, and GLTFLoader turns KHR_materials_unlit and KHR_texture_transform
  on only through that list (without it an unlit material throws, and a
  transform is dropped), but tests/tools' writers leave it out; the kiosk
  (tinygltf) reads a material's extensions either way.
- KHR_materials_pbrSpecularGlossiness, which three.js dropped (r147), is
  converted to metallic-roughness by glTF-Transform's rules (metalRough()):
  baseColorFactor = diffuseFactor, baseColorTexture = diffuseTexture (its
  texCoord and transform with it), metallicFactor 0, roughnessFactor
  1 - glossinessFactor. A matcap reads the base colour only, so the
  KHR_materials_specular and _ior that glTF-Transform adds, and the
  specular-glossiness texture's conversion, are left out.

IN and OUT: .glb (the JSON chunk rewritten, the BIN chunk as it is) or
.gltf (its buffers' URIs must be data: URIs or lie beside OUT).
"""
import json
import struct
import sys

SPEC_GLOSS = "KHR_materials_pbrSpecularGlossiness"


def used_extensions(node, found):
    """The names of every `extensions` object's members, at any depth."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "extensions" and isinstance(value, dict):
                found.update(value)
            used_extensions(value, found)
    elif isinstance(node, list):
        for value in node:
            used_extensions(value, found)
    return found


def metal_rough(material):
    """A spec-gloss material as metallic-roughness, in place."""
    ext = material.get("extensions", {})
    sg = ext.pop(SPEC_GLOSS, None)
    if sg is None:
        return
    pbr = {
        "baseColorFactor": sg.get("diffuseFactor", [1, 1, 1, 1]),
        "metallicFactor": 0.0,
        "roughnessFactor": 1.0 - sg.get("glossinessFactor", 1.0),
    }
    if "diffuseTexture" in sg:
        pbr["baseColorTexture"] = sg["diffuseTexture"]
    material["pbrMetallicRoughness"] = pbr
    if not ext:
        del material["extensions"]


def for_three(doc):
    for material in doc.get("materials", []):
        metal_rough(material)
    used = used_extensions(doc, set())
    doc["extensionsUsed"] = sorted(used)
    if not used:
        del doc["extensionsUsed"]
    required = [e for e in doc.get("extensionsRequired", []) if e in used]
    doc.pop("extensionsRequired", None)
    if required:
        doc["extensionsRequired"] = required
    return doc


def read_glb(data):
    magic, version, _ = struct.unpack_from("<4sII", data, 0)
    length, kind = struct.unpack_from("<I4s", data, 12)
    if magic != b"glTF" or version != 2 or kind != b"JSON":
        raise ValueError("not a glTF 2.0 binary with its JSON chunk first")
    return json.loads(data[20 : 20 + length]), data[20 + length :]


def write_glb(doc, rest):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)  # chunks are 4-byte aligned
    head = struct.pack("<I4s", len(text), b"JSON")
    total = 12 + len(head) + len(text) + len(rest)
    return struct.pack("<4sII", b"glTF", 2, total) + head + text + rest


def main(src, dst):
    with open(src, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        doc, rest = read_glb(data)
        out = write_glb(for_three(doc), rest)
    else:
        out = json.dumps(for_three(json.loads(data))).encode()
    with open(dst, "wb") as f:
        f.write(out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: for_three.py IN OUT")
    main(sys.argv[1], sys.argv[2])
