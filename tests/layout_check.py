#!/usr/bin/env python3
"""The layout's rules, checked on the source tree (README, "Layout").

  python3 tests/layout_check.py [SOURCE_DIR]

Fails (exit 1, one line a problem) when
  - a .h/.cc sits at the top level of model/ or solver/ (it belongs in a
    folder), or a folder with sources has no CMakeLists.txt;
  - the folders' include graph (apps/ and each folder of model/ and solver/)
    has a cycle, model/ includes solver/ or apps/, or solver/ includes apps/;
  - a folder includes another whose library its tpopt_folder_library(...
    DEPS ... PRIVATE_DEPS ...) does not name (static libraries link in any
    order, so CMake would not notice);
  - Ceres is included, or Ceres::ceres linked (directly or through another
    library), outside solver/smooth/, or gflags outside apps/;
  - a file cites a source path (model/..., solver/..., apps/..., tests/...,
    benchmarks/..., docs/...) that does not exist.
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), ".."))
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
problems = []


def rel(path):
    return os.path.relpath(path, ROOT)


def sources_under(top):
    for dirpath, _, names in os.walk(os.path.join(ROOT, top)):
        for name in sorted(names):
            if name.endswith((".h", ".cc")):
                yield os.path.join(dirpath, name)


def folder_of(path):
    """apps/ is one node (apps/tools with it); model/ and solver/ folders each one."""
    parts = rel(path).split(os.sep)
    return "apps" if parts[0] == "apps" else "/".join(parts[:-1])


def library_of(folder):
    parts = folder.split("/")
    return "tpopt_" + "_".join(parts[1:]) if parts[0] in ("model", "solver") else None


# Folders, their includes and their libraries' stated dependencies.
edges = {}
for top in ("model", "solver", "apps"):
    for path in sources_under(top):
        folder = folder_of(path)
        if folder in ("model", "solver"):
            problems.append(f"{rel(path)}: at the top level of {folder}/; put it in a folder")
            continue
        targets = edges.setdefault(folder, {})
        with open(path, encoding="utf-8") as f:
            for inc in INCLUDE.findall(f.read()):
                head = inc.split("/")[0]
                if head in ("model", "solver", "apps"):
                    target = folder_of(os.path.join(ROOT, inc))
                    if target != folder:
                        targets.setdefault(target, rel(path) + ": " + inc)
                elif head == "ceres" and not folder.startswith("solver/smooth"):
                    problems.append(f"{rel(path)}: includes <{inc}> outside solver/smooth/")
                elif head == "gflags" and folder != "apps":
                    problems.append(f"{rel(path)}: includes <{inc}> outside apps/")

stated = {}  # library -> the libraries its CMakeLists.txt names
FOLDER_CALL = re.compile(r"tpopt_folder_library\(\s*(\w+)(.*?)\)\s*$", re.S | re.M)
for folder, targets in sorted(edges.items()):
    for target, where in targets.items():
        if folder.startswith("model") and not target.startswith("model"):
            problems.append(f"{where}: model/ uses {target}/")
        if folder.startswith("solver") and target == "apps":
            problems.append(f"{where}: solver/ uses apps/")
    if folder == "apps":
        continue
    cmake = os.path.join(ROOT, folder, "CMakeLists.txt")
    if not os.path.exists(cmake):
        problems.append(f"{folder}/: no CMakeLists.txt")
        continue
    with open(cmake, encoding="utf-8") as f:
        text = re.sub(r"#.*", "", f.read())
    calls = [(m.group(1), m.group(2).split()) for m in FOLDER_CALL.finditer(text)]
    if not calls or any(name != library_of(folder) for name, _ in calls):
        problems.append(f"{rel(cmake)}: expected tpopt_folder_library({library_of(folder)} ...)")
        continue
    for name, args in calls:
        stated.setdefault(name, set()).update(args)
        if "Ceres::ceres" in args and not folder.startswith("solver/smooth"):
            problems.append(f"{rel(cmake)}: links Ceres::ceres outside solver/smooth/")
        for target, where in targets.items():
            if library_of(target) not in args:
                problems.append(f"{where}: {name} does not name {library_of(target)}")

# Ceres reaches no library outside solver/smooth/, even through another.
for name in sorted(stated):
    seen, todo = set(), [name]
    while todo:
        for dep in stated.get(todo.pop(), ()):
            if dep not in seen:
                seen.add(dep)
                todo.append(dep)
    if "Ceres::ceres" in seen and not name.startswith("tpopt_smooth"):
        problems.append(f"{name} links Ceres::ceres through its dependencies")

# Cycles, by depth-first search.
state = {}


def visit(folder, stack):
    state[folder] = "open"
    for target in sorted(edges.get(folder, {})):
        if state.get(target) == "open":
            cycle = stack[stack.index(target):] + [target]
            problems.append("include cycle: " + " -> ".join(cycle))
        elif target not in state:
            visit(target, stack + [target])
    state[folder] = "done"


for folder in sorted(edges):
    if folder not in state:
        visit(folder, [folder])

# Cited paths exist. A citation is a path under one of these folders, with
# an extension, or (model/, solver/ only) a unit named without one.
CITED = re.compile(r"(?<![\w/.-])((?:model|solver|apps|tests|benchmarks|docs)/[\w/.-]*\w)")
SCANNED = (".h", ".cc", ".md", ".txt", ".py", ".sh")
for dirpath, dirnames, names in os.walk(ROOT):
    dirnames[:] = [d for d in dirnames
                   if not d.startswith((".", "build")) and
                   rel(os.path.join(dirpath, d)) not in ("data", "tests/data", "tests/programs",
                                                         "tests/fuzz/corpus")]
    for name in names:
        if not (name.endswith(SCANNED) or name == "run"):
            continue
        path = os.path.join(dirpath, name)
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
        for number, line in enumerate(lines, 1):
            for cited in CITED.findall(line):
                cited = cited.rstrip(".")
                full = os.path.join(ROOT, cited)
                if os.path.exists(full):
                    continue
                stem_ok = any(os.path.exists(full + ext) for ext in (".h", ".cc"))
                if "." not in os.path.basename(cited) and (
                        stem_ok or not cited.startswith(("model/", "solver/"))):
                    continue  # a unit named without its extension, or prose
                problems.append(f"{rel(path)}:{number}: cites {cited}, which does not exist")

for problem in problems:
    print(problem)
print(f"layout_check: {len(problems)} problem(s) in {ROOT}")
sys.exit(1 if problems else 0)
