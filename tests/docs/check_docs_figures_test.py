#!/usr/bin/env python3
"""scripts/check-docs-figures on made-up docs: it passes a results doc whose prose quotes its
tables and names its sets' commit, and fails each way such a doc can go stale."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCRIPT = os.path.join(ROOT, "scripts", "check-docs-figures")

GOOD = """# Frames: measured

## Speed

Regenerate: `scripts/docs-figures --only speed` (build of commit abc1234def56).

| method | ms |
| --- | ---: |
| `none` | 40.0 |
| `envmap` | 50.0 |

`envmap` takes 50.0 ms, 1.25x `none` (50.0 against 40.0 ms), 25 % more; the goal is ≤ 60 ms.
"""


def write(path, text):
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run(doc, commit="abc1234def56+changes"):
    with tempfile.TemporaryDirectory() as docs:
        data = os.path.join(docs, "data", "speed")
        os.makedirs(data)
        write(os.path.join(data, "regenerate"), "true\n")
        write(os.path.join(data, "speed.json"), json.dumps({"ms": 40.0}))
        write(os.path.join(data, "machine.json"), json.dumps({"commit": commit} if commit else {}))
        write(os.path.join(docs, "frames-results.md"), doc)
        result = subprocess.run([sys.executable, SCRIPT, "--docs", docs],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        return result.returncode, result.stdout


class CheckDocsFigures(unittest.TestCase):
    def test_a_doc_that_quotes_its_tables_passes(self):
        code, out = run(GOOD)
        self.assertEqual(code, 0, out)

    def test_a_prose_figure_in_no_table_fails(self):
        code, out = run(GOOD + "\nOn the older build it took 35.6 ms.\n")
        self.assertEqual(code, 1, out)
        self.assertIn("'35.6 ms'", out)

    def test_a_ratio_of_figures_not_quoted_fails(self):
        code, out = run(GOOD + "\n`billboard` costs 2.3x `envmap`.\n")
        self.assertEqual(code, 1, out)
        self.assertIn("'2.3 x'", out)

    def test_a_stale_score_fails_and_a_quoted_one_passes(self):
        table = "\n| method | SSIM |\n| --- | ---: |\n| `envmap` | 0.917 |\n"
        code, out = run(GOOD + table + "\nIts SSIM reads 0.917 on the mirror.\n")
        self.assertEqual(code, 0, out)
        code, out = run(GOOD + table + "\nIts SSIM reads 0.880 on the mirror.\n")
        self.assertEqual(code, 1, out)
        self.assertIn("'0.880 SSIM'", out)

    def test_a_figure_a_named_test_prints_passes(self):
        code, out = run(GOOD + "\n`Srdm.AgreesWithMarching` agrees on 99.3 % of the rays.\n")
        self.assertEqual(code, 0, out)

    def test_a_set_without_a_recorded_commit_fails(self):
        code, out = run(GOOD, commit=None)
        self.assertEqual(code, 1, out)
        self.assertIn("records no commit", out)

    def test_a_doc_naming_another_commit_fails(self):
        code, out = run(GOOD.replace("abc1234def56", "0123456789ab"))
        self.assertEqual(code, 1, out)
        self.assertIn("names not the commit", out)


if __name__ == "__main__":
    unittest.main()
