# Imports a glTF file with Blender's own importer and prints what came in, as one JSON line:
#   blender --background --factory-startup --python import_counts.py -- scene.gltf
# Meshes and emitters are counted per object; a material counts as emissive when its Principled
# BSDF has a non-black emission with a strength above 0 (what an area light written as emissive
# geometry must become).
import json
import sys

import bpy
import numpy

# Blender 3.4's importer still uses numpy.bool, which NumPy 1.24 (Debian 12's) removed.
if not hasattr(numpy, "bool") or "bool" in getattr(numpy, "__former_attrs__", {}):
    numpy.bool = bool

path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)


def emissive(material):
    if not material or not material.use_nodes:
        return False
    for node in material.node_tree.nodes:
        if node.type == "BSDF_PRINCIPLED":
            colour = node.inputs["Emission"].default_value
            strength = node.inputs["Emission Strength"].default_value
            linked = node.inputs["Emission"].is_linked
            if (linked or max(colour[0], colour[1], colour[2]) > 0.0) and strength > 0.0:
                return True
        if node.type == "EMISSION":
            return True
    return False


objects = list(bpy.context.scene.objects)
meshes = [o for o in objects if o.type == "MESH"]
counts = {
    "objects": len(objects),
    "meshes": len(meshes),
    "lights": len([o for o in objects if o.type == "LIGHT"]),
    "cameras": len([o for o in objects if o.type == "CAMERA"]),
    "materials": len([m for m in bpy.data.materials if m.users > 0]),
    "emissive_objects": len([o for o in meshes if any(emissive(s.material) for s in o.material_slots)]),
    "animated_objects": len([o for o in objects if o.animation_data and o.animation_data.action]),
    "names": sorted(o.name for o in objects),
}
print("GLINT_COUNTS " + json.dumps(counts))
