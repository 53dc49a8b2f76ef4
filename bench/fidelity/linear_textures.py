"""Blender pre-script for the fidelity references: make Cycles filter colour textures in linear
light, as Obscura (and every GPU sampling an sRGB texture) does.

Cycles keeps an 8-bit sRGB image as bytes and converts to linear *after* interpolating the
encoded texels, so across a high-contrast texel edge it returns the encoded blend, which is
darker than the blend of the linear colours. That is a convention, not physics, but it made the
references of textured models differ from Obscura on every texel edge by far more than Cycles'
noise. Here every sRGB image is replaced, just before rendering, by a float image holding the
same texels decoded to linear (IEC 61966-2-1), so Cycles interpolates linear values. Non-colour
images (normal, metallic-roughness maps) are left alone. Alpha stays straight and apart from
the colour, as glTF's base colour texture defines it (see linear.alpha_mode below).

Run before the Cycles script, in the same Blender:
  blender -b --factory-startup --python linear_textures.py --python gltf_cycles.py -- ...
The render_init handler fires after the Cycles script has imported the model and built its
materials, before Cycles reads the scene.
"""
import bpy
import numpy as np


def srgb_to_linear(v):
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def linearize_images(*_):
    converted = {}
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        for node in material.node_tree.nodes:
            image = getattr(node, "image", None)
            if node.type != "TEX_IMAGE" or image is None:
                continue
            if image.colorspace_settings.name != "sRGB" or image.is_float:
                continue
            if image.name not in converted:
                w, h = image.size
                pixels = np.empty(w * h * 4, dtype=np.float32)
                image.pixels.foreach_get(pixels)  # RGBA, still sRGB-encoded, alpha straight
                pixels = pixels.reshape(-1, 4)
                pixels[:, :3] = srgb_to_linear(pixels[:, :3])
                linear = bpy.data.images.new(image.name + "-linear", w, h, alpha=True,
                                             float_buffer=True)
                linear.colorspace_settings.name = "Linear"
                # Blender holds float images premultiplied; "channel packed" keeps the colour
                # and the alpha apart, so a texel's colour survives its alpha (glTF OPAQUE
                # ignores alpha) and Cycles reads the straight colour the file holds.
                linear.alpha_mode = "CHANNEL_PACKED"
                linear.pixels.foreach_set(pixels.ravel())
                converted[image.name] = linear
                print("LINEAR_TEXTURE %s %dx%d" % (image.name, w, h))
            node.image = converted[image.name]


bpy.app.handlers.render_init.append(linearize_images)
