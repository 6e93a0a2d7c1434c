# Builds a few scenes in Blender and writes each with Blender's own glTF
# exporter, as a user's Blender export would come: the corpus test
# (tests/corpus/run.sh, expected.txt) checks the kiosk shows them.
#
#   blender -b --factory-startup --python tests/corpus/blender/export.py -- DIR
#
# (sphere-material.glb's bytes change from run to run: Blender's normals of
# the UV sphere differ in the last bit, and the exporter's vertex order
# with them; its picture does not.)
# Made with Debian 12's blender 3.4.1 (glTF exporter 3.4.50). Its Draco
# option needs libextern_draco.so, which Debian does not ship, so no file
# here is Draco-compressed by Blender (run.sh makes one with
# draco_transcoder instead).
import math
import os
import sys

import bpy


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def export(path, **options):
    bpy.ops.export_scene.gltf(filepath=path, export_format='GLB', export_animations=False,
                              **options)


def principled(name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    return mat, mat.node_tree.nodes['Principled BSDF']


def sphere_material(out):
    """A smooth UV sphere whose material has a base colour (baseColorFactor)."""
    bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=1.0)
    obj = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    mat, bsdf = principled('Paint')
    bsdf.inputs['Base Color'].default_value = (0.8, 0.25, 0.1, 1.0)
    obj.data.materials.append(mat)
    export(os.path.join(out, 'sphere-material.glb'))


def checker_image(path):
    """A 32x32 two-colour checker, saved as PNG (the exporter embeds files)."""
    size = 32
    img = bpy.data.images.new('checker', size, size)
    pixels = []
    for y in range(size):
        for x in range(size):
            on = ((x // 4) + (y // 4)) % 2
            pixels += [0.9, 0.85, 0.2, 1.0] if on else [0.1, 0.3, 0.8, 1.0]
    img.pixels = pixels
    img.filepath_raw = path
    img.file_format = 'PNG'
    img.save()
    return img


def cube_textured(out):
    """The default cube's UVs, a checker as base colour texture, through a
    Mapping node (KHR_texture_transform)."""
    bpy.ops.mesh.primitive_cube_add(size=2.0)
    obj = bpy.context.active_object
    mat, bsdf = principled('Checker')
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    tex = nodes.new('ShaderNodeTexImage')
    tex.image = checker_image(os.path.join(out, 'checker.png'))
    uv = nodes.new('ShaderNodeTexCoord')
    mapping = nodes.new('ShaderNodeMapping')
    mapping.inputs['Scale'].default_value = (2.0, 2.0, 1.0)
    mapping.inputs['Rotation'].default_value = (0.0, 0.0, math.radians(20))
    links.new(uv.outputs['UV'], mapping.inputs['Vector'])
    links.new(mapping.outputs['Vector'], tex.inputs['Vector'])
    links.new(tex.outputs['Color'], bsdf.inputs['Base Color'])
    obj.data.materials.append(mat)
    export(os.path.join(out, 'cube-textured.glb'))
    os.remove(os.path.join(out, 'checker.png'))


def tube(rings, sides, radius, length):
    """A capped tube along z, from -length/2 to length/2."""
    verts, faces = [], []
    for r in range(rings):
        z = -length / 2 + length * r / (rings - 1)
        for s in range(sides):
            a = 2 * math.pi * s / sides
            verts.append((radius * math.cos(a), radius * math.sin(a), z))
    for r in range(rings - 1):
        for s in range(sides):
            a, b = r * sides + s, r * sides + (s + 1) % sides
            faces.append((a, b, b + sides, a + sides))
    faces.append(tuple(reversed(range(sides))))
    faces.append(tuple(range((rings - 1) * sides, rings * sides)))
    return verts, faces


def skinned(out):
    """A tube skinned to a two-bone armature, the upper bone bent 60
    degrees in the pose (no animation): the kiosk shows the pose."""
    verts, faces = tube(13, 16, 0.25, 2.0)
    mesh = bpy.data.meshes.new('Tube')
    mesh.from_pydata(verts, [], faces)
    for p in mesh.polygons:
        p.use_smooth = True
    obj = bpy.data.objects.new('Tube', mesh)
    bpy.context.collection.objects.link(obj)

    arm = bpy.data.armatures.new('Rig')
    rig = bpy.data.objects.new('Rig', arm)
    bpy.context.collection.objects.link(rig)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='EDIT')
    lower = arm.edit_bones.new('Lower')
    lower.head, lower.tail = (0, 0, -1), (0, 0, 0)
    upper = arm.edit_bones.new('Upper')
    upper.head, upper.tail = (0, 0, 0), (0, 0, 1)
    upper.parent = lower
    upper.use_connect = True
    bpy.ops.object.mode_set(mode='OBJECT')

    groups = {name: obj.vertex_groups.new(name=name) for name in ('Lower', 'Upper')}
    for i, v in enumerate(verts):
        w = min(1.0, max(0.0, (v[2] + 0.3) / 0.6))
        groups['Upper'].add([i], w, 'REPLACE')
        groups['Lower'].add([i], 1.0 - w, 'REPLACE')
    obj.parent = rig
    obj.modifiers.new('Armature', 'ARMATURE').object = rig

    bend = rig.pose.bones['Upper']
    bend.rotation_mode = 'XYZ'
    bend.rotation_euler = (math.radians(60), 0, 0)
    export(os.path.join(out, 'tube-skinned.glb'), export_skins=True, export_current_frame=True)


def modifiers(out):
    """A cube under a bevel and a subdivision surface modifier, applied by
    the exporter."""
    bpy.ops.mesh.primitive_cube_add(size=2.0)
    obj = bpy.context.active_object
    bevel = obj.modifiers.new('Bevel', 'BEVEL')
    bevel.width = 0.3
    bevel.segments = 2
    obj.modifiers.new('Subdivision', 'SUBSURF').levels = 1
    bpy.ops.object.shade_smooth()
    export(os.path.join(out, 'cube-modifiers.glb'), export_apply=True)


def suzanne_colors(out):
    """Suzanne with a per-corner colour attribute (COLOR_0)."""
    bpy.ops.mesh.primitive_monkey_add(size=2.0)
    obj = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    mesh = obj.data
    colors = mesh.color_attributes.new('Col', 'BYTE_COLOR', 'CORNER')
    for loop in mesh.loops:
        x, y, z = mesh.vertices[loop.vertex_index].co
        colors.data[loop.index].color = (0.5 + 0.4 * x, 0.5 + 0.4 * y, 0.5 + 0.4 * z, 1.0)
    mesh.color_attributes.active_color = colors
    export(os.path.join(out, 'suzanne-colors.glb'), export_colors=True)


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    out = os.path.abspath(argv[0] if argv else os.path.dirname(__file__))
    for build in (sphere_material, cube_textured, skinned, modifiers, suzanne_colors):
        reset()
        build(out)


main()
