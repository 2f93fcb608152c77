#!/usr/bin/env python3
"""How many of CI's Release compile jobs a change recompiles, before CI runs.

Usage: scripts/cache-replay.py OLD_COMMIT NEW_COMMIT

A job of CI's compiler cache hits when its source lists the same files and every file it
includes (the project's own headers, followed transitively) has the same content as in a job
an earlier CI compiled. This exports both commits (git archive), configures each as CI does
(the release preset, -DCMAKE_UNITY_BUILD=ON; configure only, no build) and counts the jobs of
NEW_COMMIT that OLD_COMMIT did not have: for CMake's unity batches (CI's jobs), for one file
per job, and for groups by a hash of the file name. docs/quality-checks.md (Time) has what it
predicted for a stop and how that compared with the CI's own log.
"""
import collections
import glob
import math
import os
import re
import subprocess
import sys
import tempfile
import zlib

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def git(*args):
    return subprocess.run(['git', *args], capture_output=True, text=True, check=True).stdout


class Tree:
    """One commit, exported and configured: its files' contents and its compile jobs."""

    def __init__(self, commit, workdir):
        self.commit = commit
        self.root = os.path.join(workdir, commit)
        os.makedirs(self.root)
        archive = subprocess.run(['git', 'archive', commit], capture_output=True, check=True)
        subprocess.run(['tar', '-x', '-C', self.root], input=archive.stdout, check=True)
        subprocess.run(['cmake', '--preset', 'release', '-DCMAKE_UNITY_BUILD=ON'], cwd=self.root,
                       capture_output=True, check=True)
        self.build = os.path.join(self.root, 'build', 'release')
        self.blob = {}
        for line in git('ls-tree', '-r', commit).splitlines():
            meta, path = line.split('\t', 1)
            self.blob[path] = meta.split()[2]
        self.includes = {}

    def text(self, path):
        with open(os.path.join(self.root, path), errors='replace') as f:
            return f.read()

    def closure(self, path):
        """The file and every project file it includes, each with its content's hash."""
        seen, todo = set(), [path]
        while todo:
            p = todo.pop()
            if p in seen:
                continue
            seen.add(p)
            if p not in self.includes:
                found = []
                for inc in INCLUDE.findall(self.text(p)):
                    for cand in (os.path.normpath(os.path.join(os.path.dirname(p), inc)),
                                 os.path.normpath(inc)):
                        if cand in self.blob:
                            found.append(cand)
                            break
                self.includes[p] = found
            todo.extend(self.includes[p])
        return frozenset((p, self.blob[p]) for p in seen)

    def jobs(self):
        """{target: [member lists]}: the unity batches and the files compiled alone."""
        res = collections.defaultdict(list)
        for f in glob.glob(self.build + '/**/Unity/unity_*_cxx.cxx', recursive=True):
            target = f.split('/CMakeFiles/')[1].split('.dir/')[0]
            with open(f) as src:
                members = re.findall(r'#include "([^"]+)"', src.read())
            res[target].append([os.path.relpath(m, self.root) for m in members])
        with open(self.build + '/build.ninja') as ninja:
            for line in ninja:
                m = re.match(r'build \S+?/CMakeFiles/(\S+?)\.dir/(\S+)\.o: CXX_COMPILER__\S+ (\S+)',
                             line)
                if m and not m.group(2).startswith('Unity/'):
                    src = m.group(3)
                    if not os.path.isabs(src):
                        src = os.path.join(self.build, src)
                    rel = os.path.relpath(os.path.normpath(src), self.root)
                    if rel in self.blob:
                        res[m.group(1)].append([rel])
        return res


def keyed(tree, batches):
    """One key per job: its files in order and the contents of everything they include."""
    return [(tuple(members), frozenset().union(*(tree.closure(m) for m in members)))
            for members in batches]


def schemes(tree):
    """The same files cut three ways: CI's batches, one per file, hashed groups."""
    unity, single, hashed = [], [], []
    for members_lists in tree.jobs().values():
        unity += members_lists
        files = [m for ms in members_lists for m in ms]
        single += [[f] for f in files]
        alone = [ms[0] for ms in members_lists if len(ms) == 1]
        grouped = sorted(f for f in files if f not in alone)
        k = max(1, math.ceil(len(grouped) / 8))
        groups = collections.defaultdict(list)
        for f in grouped:
            groups[zlib.crc32(os.path.basename(f).encode()) % k].append(f)
        hashed += list(groups.values()) + [[f] for f in alone]
    return {'unity batches of 8 (CI)': unity, 'one file per job': single,
            'hashed groups': hashed}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    os.chdir(git('rev-parse', '--show-toplevel').strip())
    with tempfile.TemporaryDirectory() as work:
        old, new = Tree(sys.argv[1], work), Tree(sys.argv[2], work)
        old_schemes, new_schemes = schemes(old), schemes(new)
        for name, batches in new_schemes.items():
            before = set(keyed(old, old_schemes[name]))
            now = keyed(new, batches)
            missed = sum(1 for job in now if job not in before)
            print(f'{name}: {len(now)} jobs, {missed} recompiled ({100 * missed / len(now):.0f} %)')


if __name__ == '__main__':
    main()
