#!/usr/bin/env python3
"""Writes BUILD/tidy/compile_commands.json for clang-tidy: BUILD/compile_commands.json with every
unity source (CMake's Unity/unity_*.cxx, which #include several .cpp files of one target; CI's
trees are unity builds, docs/quality-checks.md) replaced by one entry per .cpp file it includes,
with the unity file's command. Usage: scripts/tidy_compile_db.py BUILD"""
import json
import os
import re
import sys

build = sys.argv[1]
entries = []
for e in json.load(open(os.path.join(build, "compile_commands.json"))):
    if re.search(r"/Unity/unity_[0-9]+_cxx\.cxx$", e["file"]):
        with open(e["file"]) as unity:
            for source in re.findall(r'^#include "(.+)"$', unity.read(), re.M):
                entries.append(dict(e, file=source, command=e["command"].replace(e["file"], source)))
    else:
        entries.append(e)
os.makedirs(os.path.join(build, "tidy"), exist_ok=True)
with open(os.path.join(build, "tidy", "compile_commands.json"), "w") as out:
    json.dump(entries, out, indent=1)
