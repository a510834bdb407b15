#!/usr/bin/python3
"""Prints the SSIM values that tests/eval/ssim_test.cpp pins, from scikit-image and SciPy.

Needs Debian's python3-skimage (apt install python3-skimage); run it with Debian's python3.
scikit-image's structural_similarity gives every pixel whose 11-tap window lies inside the image
(and its own mean, which crops 5 pixels at each border); at the borders it reflects the image
where mirage clamps, so the border values come from the same formula over SciPy's
gaussian_filter with mode='nearest' (with mode='reflect' the formula gives scikit-image's map).
"""
import numpy as np
import scipy
import skimage
from scipy.ndimage import gaussian_filter
from skimage.metrics import structural_similarity

W, H = 40, 28


def grid(level):
    return np.array([[level(x, y) / 255 for x in range(W)] for y in range(H)])


def pattern(x, y):
    return (x * 37 + y * 91 + (x * y) % 53) % 256


def ssim_map(a, b, mode):
    f = lambda z: gaussian_filter(z, 1.5, truncate=3.5, mode=mode)
    ux, uy = f(a), f(b)
    vx, vy, cxy = f(a * a) - ux * ux, f(b * b) - uy * uy, f(a * b) - ux * uy
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    return ((2 * ux * uy + c1) * (2 * cxy + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2))


CASES = {
    "noisy": (lambda x, y: min(255, max(0, pattern(x, y) + (x * 13 + y * 7) % 41 - 20)), pattern),
    "scrambled": (lambda x, y: (pattern(x, y) * 7 + 11) % 256, pattern),
    "brighter": (lambda x, y: min(255, (x * 6 + y * 3) % 256 + 30), lambda x, y: (x * 6 + y * 3) % 256),
}

print(f"scikit-image {skimage.__version__}, SciPy {scipy.__version__}, NumPy {np.__version__}")
for name, (test_level, reference_level) in CASES.items():
    test, reference = grid(test_level), grid(reference_level)
    mssim, full = structural_similarity(test, reference, gaussian_weights=True, sigma=1.5,
                                        use_sample_covariance=False, data_range=1.0, full=True)
    assert np.abs(ssim_map(test, reference, "reflect") - full).max() < 1e-12
    nearest = ssim_map(test, reference, "nearest")
    print(f"{name}: scikit-image mean (cropped 5) {mssim!r}")
    for x, y in [(5, 5), (12, 9), (20, 10), (20, 14), (33, 20), (34, 22)]:
        print(f"  scikit-image map({x}, {y}) = {full[y, x]!r}")
    for x, y in [(0, 0), (39, 27), (20, 0)]:
        print(f"  nearest map({x}, {y}) = {nearest[y, x]!r}")
    print(f"  nearest mean over the whole map {nearest.mean()!r}")
