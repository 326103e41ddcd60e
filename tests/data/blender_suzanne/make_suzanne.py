# Makes suzanne.glb: a metallic Suzanne on a checker-textured plane, exported by Blender's own glTF
# exporter (the case a new user tries). Run: blender -b --factory-startup --python make_suzanne.py
import os
import bpy

here = os.path.dirname(os.path.abspath(__file__))
bpy.ops.wm.read_factory_settings(use_empty=True)

# The plane: a 16 x 16 checker (two greens) repeated 4 times across it, so wrap and uv show.
image = bpy.data.images.new("checker", 16, 16)
pixels = []
for y in range(16):
    for x in range(16):
        light = (x // 4 + y // 4) % 2 == 0
        pixels += [0.8, 0.75, 0.3, 1.0] if light else [0.1, 0.35, 0.15, 1.0]
image.pixels = pixels
floor = bpy.data.materials.new("checker_floor")
floor.use_nodes = True
nodes, links = floor.node_tree.nodes, floor.node_tree.links
bsdf = nodes["Principled BSDF"]
bsdf.inputs["Roughness"].default_value = 0.8
tex = nodes.new("ShaderNodeTexImage")
tex.image = image
tex.interpolation = "Closest"
mapping = nodes.new("ShaderNodeMapping")
coords = nodes.new("ShaderNodeTexCoord")
links.new(coords.outputs["UV"], tex.inputs["Vector"])
links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
bpy.ops.mesh.primitive_plane_add(size=4.0, location=(0.0, 0.0, 0.0))
plane = bpy.context.active_object
plane.data.materials.append(floor)
for loop in plane.data.uv_layers.active.data:   # repeat the checker 4 times
    loop.uv = (loop.uv[0] * 4.0, loop.uv[1] * 4.0)

# Suzanne: gold, smooth shaded, no uvs (nothing textured on it keeps the file small).
gold = bpy.data.materials.new("gold")
gold.use_nodes = True
p = gold.node_tree.nodes["Principled BSDF"]
p.inputs["Base Color"].default_value = (1.0, 0.71, 0.29, 1.0)
p.inputs["Metallic"].default_value = 1.0
p.inputs["Roughness"].default_value = 0.3
bpy.ops.mesh.primitive_monkey_add(size=1.2, location=(0.0, 0.0, 0.75), rotation=(0.3, 0.0, 0.0))
suzanne = bpy.context.active_object
bpy.ops.object.shade_smooth()
suzanne.data.materials.append(gold)
while suzanne.data.uv_layers:
    suzanne.data.uv_layers.remove(suzanne.data.uv_layers[0])

bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.join()   # one mesh, two primitives: the per-primitive materials are the point
bpy.ops.export_scene.gltf(filepath=os.path.join(here, "suzanne.glb"), export_format="GLB",
                          export_apply=True, export_cameras=False, export_lights=False)
