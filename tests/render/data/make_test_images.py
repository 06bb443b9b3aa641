#!/usr/bin/env python3
"""Regenerates the small committed images of the SSIM/PSNR agreement test.

Natural photographs from scikit-image's sample data, downscaled, plus
variants a renderer regression produces: sensor-like noise with a partly
transparent region (exercises compositing over black), and a blur with a
brightness drift and a changed patch. Run with Debian's /usr/bin/python3.
"""
import numpy as np
from PIL import Image, ImageFilter
import skimage.data

rng = np.random.default_rng(7)


def save(array, name):
    Image.fromarray(np.clip(np.rint(array), 0, 255).astype(np.uint8), "RGBA").save(name, optimize=True)


def rgba(image, size):
    small = np.asarray(Image.fromarray(image).resize(size, Image.LANCZOS), dtype=np.float64)
    return np.concatenate([small, np.full(small.shape[:2] + (1,), 255.0)], axis=2)


cat = rgba(skimage.data.chelsea(), (128, 96))
save(cat, "chelsea_ref.png")
noisy = cat.copy()
noisy[..., :3] += rng.normal(0.0, 4.0, noisy[..., :3].shape)
noisy[60:90, 10:70, 3] = np.linspace(255, 40, 60)[None, :]  # a fade to transparent
save(noisy, "chelsea_noise.png")

coffee = rgba(skimage.data.coffee(), (120, 80))
save(coffee, "coffee_ref.png")
blurred = np.asarray(Image.fromarray(coffee.astype(np.uint8), "RGBA").filter(ImageFilter.GaussianBlur(1.2)),
                     dtype=np.float64)
blurred[..., :3] += 3.0
blurred[20:35, 70:100, :3] = [200, 40, 40]
blurred[..., 3] = 255
save(blurred, "coffee_blur.png")
