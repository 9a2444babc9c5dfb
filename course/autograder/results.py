"""Test machinery: reads one results.json for course/autograder/test.sh.
usage: results.py SCHEMA FILE
Validates FILE against SCHEMA with jsonschema when it can be imported (prints "schema: valid",
"schema: INVALID: why" or "schema: skipped: why"), then prints "total SCORE", "output TEXT" (first
line) and, per part seen in the test names ("Part N: ..."), "part N UNIT UNIT_MAX IMAGES IMAGES_MAX
TESTS" where TESTS counts its entries. Exit status 1 when FILE is not a JSON object."""
import json
import re
import sys

schema_path, path = sys.argv[1], sys.argv[2]


def no_duplicates(pairs):
    """Every JSON pathlab reads refuses a duplicate key (the last one would silently win)."""
    keys = [k for k, _ in pairs]
    if len(set(keys)) != len(keys):
        raise ValueError("duplicate key")
    return dict(pairs)


try:
    with open(path, encoding="utf-8") as f:
        data = json.load(f, object_pairs_hook=no_duplicates)
except Exception as e:  # a results file that does not parse is the failure this test looks for
    print("schema: INVALID: not JSON: %s" % e)
    sys.exit(1)
if not isinstance(data, dict):
    print("schema: INVALID: not an object")
    sys.exit(1)
try:
    import jsonschema
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    errors = sorted(jsonschema.Draft7Validator(schema).iter_errors(data), key=lambda e: list(e.path))
    if errors:
        e = errors[0]
        print("schema: INVALID: %s at %s" % (e.message, "/".join(str(p) for p in e.path) or "top level"))
    else:
        print("schema: valid")
except ImportError as e:
    print("schema: skipped: %s" % e)

print("total %g" % float(data.get("score", 0)))
print("output %s" % str(data.get("output", "")).split("\n")[0])
parts = {}
for t in data.get("tests", []):
    m = re.match(r"Part (\d)", str(t.get("name", "")))
    if not m:
        continue
    p = parts.setdefault(int(m.group(1)), [0.0, 0.0, 0.0, 0.0, 0])
    k = 0 if "unit tests" in t["name"] else 2
    p[k] += float(t.get("score", 0))
    p[k + 1] += float(t.get("max_score", 0))
    p[4] += 1
for n in sorted(parts):
    print("part %d %g %g %g %g %d" % ((n,) + tuple(parts[n])))
