#!/usr/bin/env python3
"""Prints one line per test case of a ctest run: "STATUS NAME", STATUS being run (passed), fail or
skipped; names of parameterised tests may hold spaces, so the status comes first.

ctest runs each GoogleTest suite as one test (tests/cmake/AddGTestSuites.cmake), so its JUnit file
names suites. The tests inside them come from GoogleTest's own XML, which each suite writes under
gtest-results/ beside the JUnit file. A suite that failed without a failing test in its XML (it
crashed or timed out) is printed as one failed case, "SUITE.(the suite's process)".

Usage: scripts/test-cases.py BUILD_DIR/ctest-junit.xml
"""
import pathlib
import sys
import xml.etree.ElementTree as ET


def gtest_cases(results_dir):
    """{suite: [(status, name)]} from every GoogleTest XML file under results_dir."""
    suites = {}
    for path in sorted(results_dir.glob("*/*.xml")):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError:
            continue  # a process killed while writing: its ctest entry says it failed
        for case in root.iter("testcase"):
            suite = case.get("classname", "")
            if case.find("failure") is not None:
                status = "fail"
            elif case.get("result") == "skipped" or case.get("status") == "notrun" or case.find("skipped") is not None:
                status = "skipped"
            else:
                status = "run"
            suites.setdefault(suite, []).append((status, f"{suite}.{case.get('name')}"))
    return suites


def ctest_cases(junit):
    """[(status, name)] of the JUnit file ctest writes (status: run, fail, notrun, disabled)."""
    out = []
    for case in ET.parse(junit).getroot().iter("testcase"):
        status = case.get("status", "run")
        out.append(("skipped" if status in ("notrun", "disabled") else status, case.get("name", "")))
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    junit = pathlib.Path(sys.argv[1])
    suites = gtest_cases(junit.parent / "gtest-results")
    for status, name in ctest_cases(junit):
        tests = suites.get(name)
        if tests is None:
            print(status, name)  # not a GoogleTest suite: replay, CLI and layering checks
            continue
        for test_status, test_name in tests:
            print(test_status, test_name)
        if status == "fail" and not any(s == "fail" for s, _ in tests):
            print("fail", f"{name}.(the suite's process)")


if __name__ == "__main__":
    main()
