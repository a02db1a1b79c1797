#!/usr/bin/python3
"""Unit test of scripts/bench_css_profile.py's cut points: every variant's anchor occurs exactly
once in the shader it edits, so a change to glsl/techniques/css/ that moves one fails here
instead of stopping `scripts/bench css_profile` later (two had drifted unnoticed). Run by ctest
(label unit) as bench.css_profile_anchors."""
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench_css_profile as profile  # noqa: E402


class Anchors(unittest.TestCase):
    def test_every_anchor_is_in_its_shader_once(self):
        for label, edits, _ in profile.VARIANTS + profile.ONE_LIGHT_VARIANTS:
            for name, anchor, _ in edits:
                path = os.path.join(ROOT, "glsl", profile.SHADERS, name)
                with open(path, encoding="utf-8") as f:
                    self.assertEqual(f.read().count(anchor), 1, f"{label}: {name}: {anchor!r}")

    def test_variant_dir_applies_the_edits_and_refuses_a_missing_anchor(self):
        with tempfile.TemporaryDirectory() as out:
            label, edits, _ = profile.ONE_LIGHT_VARIANTS[0]
            path = profile.variant_dir(out, 0, edits)
            name, anchor, replacement = edits[0]
            with open(os.path.join(path, profile.SHADERS, name), encoding="utf-8") as f:
                self.assertIn(replacement, f.read(), label)
            with self.assertRaises(SystemExit):
                profile.variant_dir(out, 1, [(name, "no such line in any shader", "")])


if __name__ == "__main__":
    unittest.main()
