"""Reading lacrima shot files from Python (tools/peers): JSON with // and /* */ comments.

Used by cycles_scene.py inside Blender and by compare_with_cycles.sh outside it:
    python3 tools/peers/shot_json.py frame-start SHOT    prints the shot's first frame
"""
import json
import re
import sys

_STRING_OR_COMMENT = re.compile(r'"(?:\\.|[^"\\])*"|//[^\n]*|/\*.*?\*/', re.S)


def strip_json_comments(text):
    """Drops // and /* */ comments outside strings (lacrima's shot files allow them)."""
    return _STRING_OR_COMMENT.sub(lambda m: m.group(0) if m.group(0).startswith('"') else "", text)


def load_shot(path):
    """The shot as Python data; raises OSError or ValueError (with the reason) when it cannot."""
    with open(path, encoding="utf-8") as f:
        return json.loads(strip_json_comments(f.read()))


def main(argv):
    if len(argv) != 3 or argv[1] != "frame-start":
        print("usage: shot_json.py frame-start SHOT", file=sys.stderr)
        return 2
    try:
        print(load_shot(argv[2]).get("frames", {}).get("start", 1))
    except (OSError, ValueError) as error:
        print(f"shot_json.py: {argv[2]}: cannot read the shot: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
