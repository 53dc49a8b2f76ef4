"""Blender pre-script: light the fidelity scene with an equirectangular map instead of the uniform
white world, oriented as Obscura orients `--environment FILE`.

The map is named by the environment variable OBSCURA_FIDELITY_ENVMAP (the Cycles script parses
every argument after `--`, so this cannot be one). Run before the Cycles script, in the same
Blender:
  OBSCURA_FIDELITY_ENVMAP=map.hdr blender -b --factory-startup --python environment_map.py \
      --python gltf_cycles.py -- ...
The render_init handler fires after the Cycles script has built its uniform world, before Cycles
reads the scene.

Orientation. Obscura's lat-long map (trace/environment_light.h) has row 0 looking up (+Y in
glTF's frame), its centre column looking along glTF's -Z and u growing towards +X. Blender
imports glTF's (x, y, z) as (x, -z, y) and looks up u = 0.5 - atan2(y, x) / 2pi, which puts
its centre column along Blender's +X. glTF's -Z is Blender's +Y, a quarter turn away: the
direction is turned by -90 degrees about Blender's Z before the lookup, so both renderers read
the same texel in every direction. Lookups are nearest-texel ("Closest"), as Obscura's are, and
the background is rendered rather than made transparent, so the map seen directly is part of
the image in both.
"""
import math
import os

import bpy


def use_environment_map(*_):
    path = os.environ["OBSCURA_FIDELITY_ENVMAP"]
    scene = bpy.context.scene
    world = bpy.data.worlds.new("environment-map")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    background = nodes.get("Background")
    coordinates = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "VECTOR"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(-90.0))
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(path)
    texture.image.colorspace_settings.name = "Linear"
    texture.interpolation = "Closest"
    texture.projection = "EQUIRECTANGULAR"
    links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], background.inputs["Color"])
    background.inputs["Strength"].default_value = 1.0
    world.cycles.sampling_method = "AUTOMATIC"
    scene.world = world
    scene.render.film_transparent = False
    print("ENVIRONMENT_MAP %s" % path)


bpy.app.handlers.render_init.append(use_environment_map)
