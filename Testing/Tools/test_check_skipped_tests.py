#!/usr/bin/python3
"""Tools.check-skipped-tests: Tools/check-skipped-tests.py, CI's rule that only tests labelled
shared-data may skip, on a JUnit file and a label listing as ctest writes them: a skip labelled
shared-data passes, any other skip fails naming the test, a run without skips passes.

Usage: test_check_skipped_tests.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

source = sys.argv[1]
checker = os.path.join(source, "Tools", "check-skipped-tests.py")
work = tempfile.mkdtemp(prefix="proxima-check-skipped-")


def fail(message):
    sys.exit(f"check-skipped-tests test: {message}")


def case(name, skipped):
    body = '<skipped message="SKIP_RETURN_CODE=77"/>' if skipped else ""
    status = "notrun" if skipped else "run"
    return f'<testcase name="{name}" classname="{name}" time="0" status="{status}">{body}</testcase>'


def check(cases, labels):
    """Runs the checker on a JUnit file of `cases` (name, skipped) and ctest's json-v1 listing
    of `labels` ({name: [labels]}); returns its status and output."""
    junit = os.path.join(work, "results.xml")
    with open(junit, "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n<testsuite name="t" tests="'
                  f'{len(cases)}">' + "".join(case(n, s) for n, s in cases) + "</testsuite>\n")
    listing = os.path.join(work, "labels.json")
    with open(listing, "w") as out:
        json.dump({"kind": "ctestInfo", "tests": [
            {"name": n, "properties": [{"name": "LABELS", "value": v}]} for n, v in labels.items()
        ]}, out)
    done = subprocess.run(["/usr/bin/python3", checker, work, junit, "--labels", listing],
                          capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


labels = {"Provenance/Read.screw": ["unit", "shared-data"], "Read.bunny": ["unit"],
          "proxima.remote-runs": ["cli"]}
status, output = check([("Provenance/Read.screw", True), ("Read.bunny", False),
                        ("proxima.remote-runs", False)], labels)
if status != 0 or "1 skipped, 1 of them labelled shared-data" not in output:
    fail(f"a shared-data skip was refused: {status} {output!r}")
status, output = check([("Provenance/Read.screw", True), ("Read.bunny", True),
                        ("proxima.remote-runs", False)], labels)
if status != 1 or "skipped outside shared-data: Read.bunny" not in output:
    fail(f"a unit skip passed: {status} {output!r}")
status, output = check([("Provenance/Read.screw", False), ("Read.bunny", False)], labels)
if status != 0 or "0 skipped" not in output:
    fail(f"a run without skips failed: {status} {output!r}")
print("check-skipped-tests: shared-data skips pass, others fail naming the test")
