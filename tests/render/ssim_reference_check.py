#!/usr/bin/env python3
"""Independent reference for `recoil compare` metrics.

Usage: ssim_reference_check.py ACTUAL.png REFERENCE.png
Prints one line of JSON: {"ssim": f, "psnr": f or null, "max_difference": f}
computed by scikit-image on the same definition recoil uses: both images
composited over black (straight alpha), encoded values in [0,1]; SSIM on luma
Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' with Gaussian weights (sigma 1.5),
population covariance, data range 1; PSNR over R, G, B with data range 1.
Exit 3 when scikit-image or Pillow is missing (the GoogleTest then skips).
"""
import json
import sys

try:
    import numpy as np
    from PIL import Image
    from skimage.metrics import peak_signal_noise_ratio, structural_similarity
except ImportError as error:  # pragma: no cover - depends on the machine
    print(f"missing module: {error}", file=sys.stderr)
    sys.exit(3)


def composited_rgb(path):
    rgba = np.asarray(Image.open(path).convert("RGBA"), dtype=np.float64) / 255.0
    return rgba[..., :3] * rgba[..., 3:4]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    actual = composited_rgb(sys.argv[1])
    reference = composited_rgb(sys.argv[2])
    weights = np.array([0.2126, 0.7152, 0.0722])
    ssim = structural_similarity(actual @ weights, reference @ weights, gaussian_weights=True, sigma=1.5,
                                 use_sample_covariance=False, data_range=1.0)
    identical = np.array_equal(actual, reference)
    psnr = None if identical else float(peak_signal_noise_ratio(reference, actual, data_range=1.0))
    max_difference = float(np.max(np.abs(actual - reference)))
    print(json.dumps({"ssim": float(ssim), "psnr": psnr, "max_difference": max_difference}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
