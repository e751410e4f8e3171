#!/usr/bin/python3
"""Fails if a ctest run skipped a test outside the label shared-data.

The tests that need files only PROXIMA_SHARED_DATA has (the meshes that may not ship, the
person-like probe paths) carry the label shared-data and skip, saying so, where it is absent;
any other skip is a test that did not run for no reason CI accepts. Reads the run's JUnit file
(`ctest --output-junit FILE`) and the tests' labels (`ctest --show-only=json-v1`), prints the
skipped tests, and exits 1 if one of them is not labelled shared-data.

Usage: check-skipped-tests.py BUILD_DIR JUNIT_FILE [--labels JSON_FILE]
(--labels: the json-v1 listing from a file instead of running ctest on BUILD_DIR)
"""
import json
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

ACCEPTED = "shared-data"


def labels_of(listing):
    """{test name: [labels]} from ctest's json-v1 listing."""
    result = {}
    for test in listing.get("tests", []):
        labels = []
        for prop in test.get("properties", []):
            if prop.get("name") == "LABELS":
                labels = list(prop.get("value", []))
        result[test["name"]] = labels
    return result


def skipped_tests(junit_file):
    """The names of the test cases the JUnit file reports as skipped."""
    root = ElementTree.parse(junit_file).getroot()
    return [case.get("name") for case in root.iter("testcase")
            if case.find("skipped") is not None]


def main():
    arguments = sys.argv[1:]
    if len(arguments) not in (2, 4) or (len(arguments) == 4 and arguments[2] != "--labels"):
        sys.exit(__doc__.strip().splitlines()[-2])
    build, junit_file = arguments[0], arguments[1]
    if len(arguments) == 4:
        with open(arguments[3]) as stream:
            listing = json.load(stream)
    else:
        shown = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"],
                               capture_output=True, text=True, check=True)
        listing = json.loads(shown.stdout)
    labels = labels_of(listing)
    skipped = skipped_tests(junit_file)
    refused = [name for name in skipped if ACCEPTED not in labels.get(name, [])]
    accepted = len(skipped) - len(refused)
    print(f"check-skipped-tests: {len(skipped)} skipped, {accepted} of them labelled {ACCEPTED}")
    for name in refused:
        print(f"check-skipped-tests: skipped outside {ACCEPTED}: {name}")
    if refused:
        sys.exit(1)


if __name__ == "__main__":
    main()
