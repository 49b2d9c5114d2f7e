#!/usr/bin/env python3
"""An independent transcription of the map hash defined in shared/cspace/.../map_hash.hpp.

It prints the test vectors that test/cspace/map_hash_test.cpp pins, so that the C++ code is
checked against the written definition rather than against its own output.
Run: python3 test/cspace/map_hash_reference.py
"""

MASK = (1 << 64) - 1
BLOCK_CELLS = 512
BLOCK_WORDS = BLOCK_CELLS // 64


def mix(x):
    x ^= x >> 33
    x = (x * 0xFF51AFD7ED558CCD) & MASK
    x ^= x >> 33
    x = (x * 0xC4CEB9FE1A85EC53) & MASK
    x ^= x >> 33
    return x


def map_hash(cells, cell_count):
    """cells: the set of forbidden cell indices."""
    blocks = (cell_count + BLOCK_CELLS - 1) // BLOCK_CELLS
    combined = 0
    for b in range(blocks):
        k = mix(b + 1)
        for w in range(BLOCK_WORDS):
            word = 0
            for bit in range(64):
                if b * BLOCK_CELLS + w * 64 + bit in cells:
                    word |= 1 << bit
            k = mix(k ^ word)
        combined ^= k
    return mix(mix(cell_count) ^ combined)


def map_hash_with_cameras(hash_value, healthy_cameras, camera_count):
    """The hash a map chunk carries: the map hash bound to the camera counts."""
    counts = (healthy_cameras << 32) | camera_count
    return hash_value ^ mix(mix(counts ^ 0x9E3779B97F4A7C15))


def map_hash_with_speed_reduction(hash_value, reduction_permille):
    """The chunk's hash bound to the speed reduction as well (none: unchanged)."""
    if reduction_permille == 0:
        return hash_value
    return hash_value ^ mix(mix(reduction_permille ^ 0xD1B54A32D192ED03))


VECTORS = [
    ("one free cell", set(), 1),
    ("100 cells: 0, 5..9, 99", {0, 5, 6, 7, 8, 9, 99}, 100),
    ("10000 cells: 4090..4199, 9999", set(range(4090, 4200)) | {9999}, 10000),
    ("1000 cells: 500..524", set(range(500, 525)), 1000),
    ("4096 cells, all forbidden", set(range(4096)), 4096),
]

if __name__ == "__main__":
    for name, cells, count in VECTORS:
        print(f"{name}: 0x{map_hash(cells, count):016X}")
    for healthy, count in [(4, 4), (3, 4), (0, 0)]:
        bound = map_hash_with_cameras(map_hash(set(), 1), healthy, count)
        print(f"one free cell, {healthy} of {count} cameras: 0x{bound:016X}")
    for reduction in [500, 1000]:
        bound = map_hash_with_speed_reduction(map_hash_with_cameras(map_hash(set(), 1), 4, 4), reduction)
        print(f"one free cell, 4 of 4 cameras, speed reduced by {reduction} permille: 0x{bound:016X}")
