#!/usr/bin/env bash
# tools/mutate-shaders.sh — mutation testing of the composition sweep (issue #38, point 4).
#
# What it does
#   For each GLSL file under shaders/ (implementations `<Slot>/<name>.glsl`, and separately the
#   include files: shaders/common/*.glsl and the helpers in slot folders such as
#   RayTraversal/march.glsl) it plants ONE fault per mutant and asks the sweep
#   (`volren permutations --render`) whether any check notices. Each mutant is one operator at
#   one site; at most --max-sites sites per operator and file, spread evenly over the file:
#     return    `return EXPR;` -> a constant of the function's return type (0, or 1 where EXPR
#               already is that constant): `return vec4(0.0);`, `return 0.0;`, ...
#     sign      binary `a + b` <-> `a - b` (and `+=` <-> `-=`); never `++`/`--`, `1e-4`, #lines
#     swizzle   `.x` <-> `.y`, `.z` -> `.y`, `.w` -> `.z`, `.r` <-> `.g`, `.b` -> `.g`,
#               `.a` -> `.r`; longer swizzles swap their first two components (`.xyz` -> `.yxz`)
#     offbyone  an integer literal N -> N+1 on a line with a comparison (loop bounds, `i == n - 1`)
#     compare   `<` <-> `<=`, `>` <-> `>=`
#     opacity   the opacity correction dropped: `pow(B, E)` -> `(B)` (so `1.0 - pow(1.0 - a, s)`
#               becomes `a`), `volren_opticalDepth(a, ratio)` -> `volren_opticalDepth(a, 1.0)`
#               (no step-length correction), `volren_opacityFromDepth(t)` -> `min(t, 1.0)`
#     float     a float literal v -> v/2 (`0.5` -> `0.25`), `0.0` -> `1.0` (no exponent literals:
#               they are epsilons and sentinels, their mutants are equivalent)
#   Comments and preprocessor lines are never mutated, and a mutant that differs from the
#   original only in whitespace or comments (or duplicates another mutant) is dropped.
#
#   A mutant is a folder holding only the mutated file at its relative path, put first on
#   VOLREN_SHADER_PATH (the registry reads every shader file, implementations and includes alike,
#   from the first folder on the path that has it: ShaderFunctionRegistry::locate). The sweep:
#     implementation Slot=name:   volren permutations --render --pairwise --where Slot=name
#       (the pairwise cover of the compositions choosing it; if there are none: --where Slot=name
#       --count K over the space instead)
#     template slots (ClipPosition, ClipRay) and include files: the whole pairwise cover
#       (--where cannot select a clip instance: Composition::functionFor answers the slot's
#       default for a template slot, so `--where ClipPosition=box` selects nothing)
#   Before the mutants of a file, the same sweep runs once with the UNMUTATED copy on the path
#   (the baseline, with --dump: which compositions contain the file, `// ---- FILE ----`, and
#   their images). A mutant is
#     killed     the sweep reports a `FAILED <key>: <check>` that the baseline did not (or it
#                crashed / timed out); the first such check is recorded. `link` = killed by
#                link (it did not compile): trivially killed, scored separately. (Not simply
#                "exits non-zero": a baseline may fail compositions of its own.)
#     survived   no new failure. Its dumped images are compared with the baseline's: identical
#                (within 1e-6, float rounding of a recompiled shader) = equivalent on the sweep's
#                scene, no check could see it; different = a change that no check caught.
#     unreached  no composition of the sweep contains the file (e.g. the multi-volume traversals:
#                the sweep's space is single-volume), nothing is run.
#     error      the harness did not run twice, or the binary was rebuilt during each of 4 tries.
#   Another build may relink build/bin/volren or build/lib/*.so at any time: a mutant whose run
#   saw the binary change is run again against a baseline of the new binary.
#   The first mutant of every run is a sanity mutant (a syntax error in the first selected file
#   that is reached): it must be killed by `link`, or the path override is not in effect and the
#   tool stops.
#
# Spaces (--space)
#   The sweep's default space (max 1 clip instance, 1 light: ~42M compositions) took ~2.2 min
#   to enumerate per volren run on a loaded 2-core machine before commit 67f8db4 (about 50 s
#   since, unloaded), before anything renders (a full-space
#   `--where` without `--pairwise` scans it: ~3.3 min). `auto` (default) runs each file in the
#   smallest space that reaches it: `0/1` (no clip instances, up to 1 light: 2.8M compositions,
#   ~10 s) for everything but the clip slots, which get `1/0` (580K, but ~65 s). `full` is the
#   sweep's own `1/1`; `I/L` sets --max-instances I --max-lights L.
#
# Options
#   --slot SLOT        only files in shaders/SLOT/ (repeatable)
#   --file PATH        only this file (shaders/Gradient/central.glsl or Gradient/central.glsl;
#                      repeatable)
#   --kind K           impl | include | all (default all)
#   --ops LIST         comma-separated operators (default all: return,sign,swizzle,offbyone,
#                      compare,opacity,float)
#   --max-sites M      sites per operator and file (default 3)
#   --jobs J           mutants run in parallel (default 1)
#   --out DIR          where report.tsv, summary.txt, logs/ and mutants/ go (default: mktemp -d)
#   --space S          auto | full | I/L (default auto)
#   --count K          compositions for an implementation the pairwise cover never chooses
#                      (default 6)
#   --timeout S        per volren run (default: 5 x the file's baseline + 120 s)
#   --volren PATH      the binary (default build/bin/volren)
#   --dry-run          list the mutants (report.tsv with result `planned`), run nothing
#   --no-sanity        skip the sanity mutant
#   --modelled         sweep only the compositions whose every implementation the CPU reference
#                      models (`volren permutations --modelled`): each of them is compared with
#                      the reference, so changed values are seen; an implementation the
#                      reference does not model is then only reached by the --count fallback
#
# How long
#   Per mutant, one volren run (measured on 2 cores, Dec 2026): ~10 s to enumerate the 0/1 space
#   plus the cover rendered on llvmpipe with its variants and reference images: 11-20 s for an
#   implementation (its cover: 43-69 compositions), 30-55 s for an include file (the whole
#   cover, 69), ~70 s for a clip implementation (1/0 space); 3-4x that while another build
#   runs. Plus one baseline per file and the sanity mutant. All 81 files at M=3: 642 mutants
#   (62 of them in the unreached multi-volume files, which cost a baseline only), ~4-5 h at
#   --jobs 1 on an otherwise idle machine. `--dry-run` counts the mutants of a selection; a real
#   run's summary estimates all files from its own seconds per mutant.
#
# Output: report.tsv (file, operator, line, original, mutated, result, check, seconds, kind,
# sweep, detail), summary.txt (mutants, killed by link / by other checks, survived, scores,
# survivors with file:line and the mutated line). Exit status 0 unless the sanity mutant failed
# or the arguments were wrong; survivors are results, not errors.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
exec /usr/bin/python3 - "$root" "$@" <<'PY'
import argparse, array, glob, math, os, re, shutil, subprocess, sys, tempfile, threading, time
from concurrent.futures import ThreadPoolExecutor

ROOT = sys.argv[1]
SHADERS = os.path.join(ROOT, "shaders")
OPS = ["return", "sign", "swizzle", "offbyone", "compare", "opacity", "float"]
TEMPLATE_SLOTS = {"ClipPosition", "ClipRay"}

ap = argparse.ArgumentParser(prog="tools/mutate-shaders.sh", description="mutation testing of the composition sweep")
ap.add_argument("--slot", action="append", default=[])
ap.add_argument("--file", action="append", default=[])
ap.add_argument("--kind", choices=["impl", "include", "all"], default="all")
ap.add_argument("--ops", default=",".join(OPS))
ap.add_argument("--max-sites", type=int, default=3)
ap.add_argument("--jobs", type=int, default=1)
ap.add_argument("--out", default="")
ap.add_argument("--space", default="auto")
ap.add_argument("--count", type=int, default=6)
ap.add_argument("--timeout", type=float, default=0.0)
ap.add_argument("--volren", default=os.path.join(ROOT, "build", "bin", "volren"))
ap.add_argument("--dry-run", action="store_true")
ap.add_argument("--no-sanity", action="store_true")
ap.add_argument("--modelled", action="store_true")
args = ap.parse_args(sys.argv[2:])
ops = [o.strip() for o in args.ops.split(",") if o.strip()]
for o in ops:
    if o not in OPS: ap.error("unknown operator '%s' (known: %s)" % (o, ",".join(OPS)))
if args.space not in ("auto", "full") and not re.fullmatch(r"\d/\d", args.space):
    ap.error("--space is auto, full or I/L")
if not os.access(args.volren, os.X_OK): ap.error(args.volren + ": no volren binary (build it first)")
out = os.path.abspath(args.out or tempfile.mkdtemp(prefix="volren-mutants-"))
os.makedirs(os.path.join(out, "logs"), exist_ok=True)
os.makedirs(os.path.join(out, "mutants"), exist_ok=True)
print_lock = threading.Lock()
def say(*a):
    with print_lock: print(*a, flush=True)

# ---------------------------------------------------------------- the registry's implementations
def implementations():
    """{slot: [names]} from `volren render --help-settings`."""
    text = subprocess.run([args.volren, "render", "--help-settings"], capture_output=True, text=True).stdout
    impls, on = {}, False
    for line in text.splitlines():
        if line.startswith("Implementations per slot"): on = True; continue
        m = re.match(r"\s+(\w+)\s+\(\w+\):\s*([^\[]*)", line) if on else None
        if m: impls[m.group(1)] = [n.strip() for n in m.group(2).split(",") if n.strip()]
    if not impls: sys.exit("cannot read the implementations from `volren render --help-settings`")
    return impls

IMPLS = implementations()

def classify(rel):
    """('impl', slot, name) or ('include', None, None) for a file relative to shaders/."""
    parts = rel.split("/")
    name = os.path.splitext(parts[-1])[0]
    if len(parts) == 2 and parts[0] in IMPLS:
        return ("impl", parts[0], name) if name in IMPLS[parts[0]] else ("include", None, None)
    if len(parts) == 2 and parts[0] != "common":  # e.g. MultiVolume/sum_of_media.glsl: a RayTraversal
        owners = [s for s, names in IMPLS.items() if name in names and name != "null"]
        if len(owners) == 1: return ("impl", owners[0], name)
    return ("include", None, None)

def files(filtered=True):
    chosen = []
    for d, _, names in os.walk(SHADERS):
        for n in names:
            rel = os.path.relpath(os.path.join(d, n), SHADERS).replace(os.sep, "/")
            if not n.endswith(".glsl") or rel == "slots.glsl" or rel.startswith("Overlay/"): continue
            chosen.append(rel)
    chosen.sort()
    if not filtered: return chosen
    if args.file:
        want = set()
        for f in args.file:
            f = os.path.relpath(os.path.abspath(f), SHADERS) if os.path.exists(f) else f
            f = f.replace(os.sep, "/")
            if f.startswith("shaders/"): f = f[len("shaders/"):]
            if f not in chosen: sys.exit("--file %s: not a shader file under shaders/" % f)
            want.add(f)
        chosen = [f for f in chosen if f in want]
    if args.slot:
        chosen = [f for f in chosen if f.split("/")[0] in args.slot]
    if args.kind != "all":
        chosen = [f for f in chosen if classify(f)[0] == args.kind]
    return chosen

# ---------------------------------------------------------------- mutation operators
def mask(text):
    """The text with comments and preprocessor lines blanked (same length, newlines kept)."""
    out, i, n = list(text), 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i); j = n if j < 0 else j
            for k in range(i, j): out[k] = " "
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2); j = n if j < 0 else j + 2
            for k in range(i, j):
                if out[k] != "\n": out[k] = " "
            i = j
        else:
            i += 1
    pos = 0
    for line in "".join(out).split("\n"):
        if line.lstrip().startswith("#"):
            for k in range(pos, pos + len(line)): out[k] = " "
        pos += len(line) + 1
    return "".join(out)

def normal(text):
    return re.sub(r"\s+", " ", mask(text)).strip()

def close_paren(c, i):
    """Index of the `)` matching the `(` at c[i]."""
    depth = 0
    for k in range(i, len(c)):
        if c[k] == "(": depth += 1
        elif c[k] == ")":
            depth -= 1
            if depth == 0: return k
    return -1

def split_args(c, lo, hi):
    """Top-level comma positions in c[lo:hi]."""
    depth, commas = 0, []
    for k in range(lo, hi):
        if c[k] in "([": depth += 1
        elif c[k] in ")]": depth -= 1
        elif c[k] == "," and depth == 0: commas.append(k)
    return commas

TYPES = r"(?:void|float|double|int|uint|bool|[biud]?vec[234]|d?mat[234](?:x[234])?|\w+)"

def functions(c):
    """[(body_start, body_end, return_type)] of the top-level function definitions."""
    out, depth, start, typ = [], 0, 0, None
    for k, ch in enumerate(c):
        if ch == "{":
            if depth == 0:
                head = c[max(0, c.rfind(";", 0, k), c.rfind("}", 0, k)) + 1:k]
                m = re.search(r"\b(" + TYPES + r")\s+\w+\s*\([^{}]*\)\s*$", head)
                typ, start = (m.group(1) if m else None), k
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0 and typ: out.append((start, k, typ))
    return out

def constant(typ, expr):
    e = re.sub(r"\s+", "", expr)
    vec = re.fullmatch(r"([biud]?)vec([234])", typ)
    if typ == "float": zero, one = "0.0", "1.0"
    elif typ == "int": zero, one = "0", "1"
    elif typ == "uint": zero, one = "0u", "1u"
    elif typ == "bool": zero, one = "false", "true"
    elif vec:
        z, o = {"": ("0.0", "1.0"), "i": ("0", "1"), "u": ("0u", "1u"), "b": ("false", "true"), "d": ("0.0", "1.0")}[vec.group(1)]
        zero, one = "%s(%s)" % (typ, z), "%s(%s)" % (typ, o)
    elif re.fullmatch(r"d?mat[234](x[234])?", typ): zero, one = typ + "(0.0)", typ + "(1.0)"
    else: return None  # void or a struct
    return one if e in (zero, zero.replace(".0", ".")) else zero

SWAP = {"x": "y", "y": "x", "z": "y", "w": "z", "r": "g", "g": "r", "b": "g", "a": "r"}

def sites(text, op):
    """[(start, end, replacement)] of operator `op` in text, in file order."""
    c, found = mask(text), []
    if op == "return":
        for (lo, hi, typ) in functions(c):
            for m in re.finditer(r"\breturn\b", c[lo:hi]):
                s = lo + m.start(); e = s; depth = 0
                while e < hi and not (c[e] == ";" and depth == 0):
                    depth += c[e] in "([" ; depth -= c[e] in ")]"; e += 1
                expr = c[s + 6:e].strip()
                const = constant(typ, expr) if expr else None
                if const: found.append((s, e + 1, "return %s;" % const))
    elif op == "sign":
        for m in re.finditer(r"(?<=[\w)\]])(\s+)([+-])(=?)(\s+)(?=[\w(.\-])", c):
            before = c[:m.start()].rstrip()
            if re.search(r"\breturn$", before) or re.search(r"\d[eE]$", before): continue
            flipped = "-" if m.group(2) == "+" else "+"
            found.append((m.start(2), m.end(2), flipped))
    elif op == "swizzle":
        for m in re.finditer(r"(?<=[A-Za-z_\])])\.([xyzw]{1,4}|[rgba]{1,4})\b", c):
            comp = m.group(1)
            if len(comp) == 1: new = SWAP[comp]
            elif comp[0] != comp[1]: new = comp[1] + comp[0] + comp[2:]
            else: continue
            found.append((m.start(1), m.end(1), new))
    elif op == "offbyone":
        pos = 0
        for line in c.split("\n"):
            if re.search(r"<=|>=|==|!=|(?<![<>])[<>](?![<>])", line):
                for m in re.finditer(r"(?<![\w.])(\d+)(?![\w.])", line):
                    found.append((pos + m.start(1), pos + m.end(1), str(int(m.group(1)) + 1)))
            pos += len(line) + 1
    elif op == "compare":
        for m in re.finditer(r"(?<![<>=!])(<=|>=|<(?![<=])|>(?![>=]))", c):
            found.append((m.start(), m.end(), {"<": "<=", "<=": "<", ">": ">=", ">=": ">"}[m.group(1)]))
    elif op == "opacity":
        for m in re.finditer(r"\b(pow|volren_opticalDepth|volren_opacityFromDepth)\s*\(", c):
            if re.search(r"\b(void|float|int|bool|[biu]?vec[234])\s+$", c[max(0, m.start() - 16):m.start()]):
                continue  # the definition, not a call
            o = m.end() - 1; e = close_paren(c, o)
            if e < 0: continue
            commas = split_args(c, o + 1, e)
            name = m.group(1)
            if name == "pow" and len(commas) == 1:
                found.append((m.start(), e + 1, "(" + text[o + 1:commas[0]].strip() + ")"))
            elif name == "volren_opticalDepth" and len(commas) == 1:
                found.append((commas[0] + 1, e, " 1.0"))
            elif name == "volren_opacityFromDepth" and not commas:
                found.append((m.start(), e + 1, "min(" + text[o + 1:e].strip() + ", 1.0)"))
    elif op == "float":
        for m in re.finditer(r"(?<![\w.])(\d+\.\d*|\.\d+)(?![\w.])", c):
            v = float(m.group(1))
            new = "1.0" if v == 0.0 else format(v / 2.0, ".10g")
            if not re.search(r"[.eE]", new): new += ".0"
            found.append((m.start(1), m.end(1), new))
    return found

def spread(items, m):
    if len(items) <= m: return items
    if m <= 1: return items[:1]
    return [items[round(i * (len(items) - 1) / (m - 1))] for i in range(m)]

def line_span(text, s, e):
    lo = text.rfind("\n", 0, s) + 1
    hi = text.find("\n", e); hi = len(text) if hi < 0 else hi
    return lo, hi

def one_line(t):
    return re.sub(r"\s+", " ", t).strip()

def mutants_of(rel, text):
    out, seen = [], {normal(text)}
    for op in ops:
        for (s, e, repl) in spread(sites(text, op), args.max_sites):
            mutated = text[:s] + repl + text[e:]
            key = normal(mutated)
            if key in seen: continue  # only whitespace/comments changed, or a duplicate
            seen.add(key)
            lo, hi = line_span(text, s, e)
            out.append({"file": rel, "op": op, "line": text.count("\n", 0, s) + 1,
                        "original": one_line(text[lo:hi]),
                        "mutated": one_line(text[lo:s] + repl + text[e:hi]), "text": mutated})
    return out

def sanity_mutant(rel, text):
    c = mask(text)
    k = c.find("{")
    if k < 0: return None
    mutated = text[:k + 1] + " volren_mutation_syntax_error @@ ;" + text[k + 1:]
    lo, hi = line_span(text, k, k)
    return {"file": rel, "op": "sanity", "line": text.count("\n", 0, k) + 1, "original": one_line(text[lo:hi]),
            "mutated": one_line(mutated[lo:hi + 33]), "text": mutated}

# ---------------------------------------------------------------- the sweep
def space_of(rel):
    kind, slot, _ = classify(rel)
    if args.space == "full": return (1, 1)
    if args.space != "auto": return tuple(int(x) for x in args.space.split("/"))
    return (1, 0) if slot in TEMPLATE_SLOTS else (0, 1)

def sweep_args(rel, fallback=False):
    kind, slot, name = classify(rel)
    inst, lights = space_of(rel)
    a = ["permutations", "--render", "--max-instances", str(inst), "--max-lights", str(lights)]
    if kind == "impl" and slot not in TEMPLATE_SLOTS:
        a += ["--where", "%s=%s" % (slot, name)] + (["--count", str(args.count)] if fallback else ["--pairwise"])
    else:
        a += ["--pairwise"]
    if args.modelled and not fallback: a += ["--modelled"]
    return a

def run_volren(vargs, overlay, log, timeout):
    """(rc, output, seconds); rc None on timeout. `overlay` goes first on VOLREN_SHADER_PATH."""
    env = dict(os.environ)
    env["VOLREN_SHADER_PATH"] = overlay + ((os.pathsep + env["VOLREN_SHADER_PATH"]) if env.get("VOLREN_SHADER_PATH") else "")
    t0 = time.time()
    try:
        p = subprocess.run([args.volren] + vargs, env=env, capture_output=True, text=True, timeout=timeout or None,
                           cwd=ROOT)
        rc, output = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired as e:
        rc, output = None, ((e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or ""))
    secs = time.time() - t0
    with open(log, "w") as f:
        f.write("VOLREN_SHADER_PATH=%s %s %s\n# rc %s, %.1f s\n%s" % (overlay, args.volren, " ".join(vargs), rc, secs, output))
    return rc, output, secs

def failures(output):
    """[(key, check)] of the FAILED lines."""
    out = []
    for line in output.splitlines():
        m = re.match(r"FAILED (.*?;): (\w+): ", line)
        if m: out.append((m.group(1), m.group(2)))
    return out

def rendered(output):
    m = re.search(r"rendered (\d+), failures (\d+)", output)
    return int(m.group(1)) if m else None

def image_difference(base_dump, dump):
    """(compositions compared, how many differ, largest difference) of the dumped first frames."""
    compared, differ, worst = 0, 0, 0.0
    if not (os.path.isdir(base_dump) and os.path.isdir(dump)): return 0, 0, 0.0
    for n in os.listdir(dump):
        # INDEX.rgba: a composition's first frame (not INDEX.reference.rgba, without.rgba)
        if not re.fullmatch(r"\d+\.rgba", n) or not os.path.exists(os.path.join(base_dump, n)): continue
        a, b = array.array("f"), array.array("f")
        with open(os.path.join(base_dump, n), "rb") as f: a.frombytes(f.read())
        with open(os.path.join(dump, n), "rb") as f: b.frombytes(f.read())
        compared += 1
        if a.tobytes() != b.tobytes():
            differ += 1
            d = max((abs(x - y) if math.isfinite(x - y) else math.inf) for x, y in zip(a, b)) if len(a) == len(b) else math.inf
            worst = max(worst, d)
    return compared, differ, worst

def overlay_dir(tag, rel, text):
    d = os.path.join(out, "mutants", tag)
    path = os.path.join(d, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f: f.write(text)
    return d

baselines, baseline_lock = {}, threading.Lock()

def binary_stamp():
    """Modification times and sizes of volren and its libraries: another build may relink them
    while this runs, and a mutant must be judged against a baseline of the same binary."""
    paths = [args.volren] + glob.glob(os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(args.volren))), "lib", "*.so*"))
    stamp = []
    for p in sorted(paths):
        try:
            st = os.stat(p); stamp.append((p, st.st_mtime_ns, st.st_size))
        except OSError:
            stamp.append((p, None, None))
    return tuple(stamp)

def baseline(rel, text):
    """The unmutated file's sweep, cached per file while the binary stays the same."""
    with baseline_lock:
        if rel in baselines and baselines[rel].get("stamp") == binary_stamp(): return baselines[rel]
        for attempt in range(5):
            stamp = binary_stamp()
            b = take_baseline(rel, text)
            if binary_stamp() == stamp: break
            say("  the binary changed during the baseline of %s: once more in 30 s" % rel)
            time.sleep(30)
        b["stamp"] = stamp
        baselines[rel] = b
        return b

def take_baseline(rel, text):
    """The unmutated file's sweep: {args, failed, seconds, reached, rendered, dump} or {args, error}."""
    tag = "baseline-" + rel.replace("/", "_").replace(".glsl", "")
    overlay = overlay_dir(tag, rel, text)
    marker = re.compile(r"^// ---- %s( \(instance \d+\))? ----$" % re.escape(rel), re.M)  # template slots: "(instance k)"
    b = None
    for fallback in (False, True):
        vargs = sweep_args(rel, fallback)
        if fallback and "--where" not in vargs: break
        dump = os.path.join(out, "logs", tag + ("-fallback" if fallback else "") + "-dump")
        shutil.rmtree(dump, ignore_errors=True)
        for attempt in (1, 2):
            rc, output, secs = run_volren(vargs + ["--dump", dump], overlay,
                                          os.path.join(out, "logs", tag + ("-fallback" if fallback else "") + ".log"), 0)
            if rc in (0, 1) and rendered(output) is not None: break
            time.sleep(30)
        if rendered(output) is None:
            b = {"args": vargs, "error": "baseline sweep did not run (rc %s; see logs/%s.log)" % (rc, tag)}
            break
        reached = 0
        if os.path.isdir(dump):
            for n in os.listdir(dump):
                if n.endswith(".frag"):
                    with open(os.path.join(dump, n), errors="replace") as f:
                        reached += bool(marker.search(f.read()))
        b = {"args": vargs, "failed": set(failures(output)), "seconds": secs, "reached": reached,
             "rendered": rendered(output), "fallback": fallback, "dump": dump}
        if reached: break
    if "error" in b: say("  baseline %s: %s" % (rel, b["error"]))
    else:
        say("  baseline %s: %d rendered, %d contain it, %d failures of its own, %.0f s (%s)" % (
            rel, b["rendered"], b["reached"], len(b["failed"]), b["seconds"], " ".join(b["args"][1:])))
    return b

def run_mutant(idx, m, originals):
    rel = m["file"]
    tag = "%04d-%s-%s-L%d" % (idx, rel.replace("/", "_").replace(".glsl", ""), m["op"], m["line"])
    overlay = overlay_dir(tag, rel, m["text"])
    dump = os.path.join(out, "logs", tag + "-dump")
    stable = False
    for attempt in range(4):
        b = baseline(rel, originals[rel])  # taken again if the binary changed since
        m["sweep"] = " ".join(b["args"][1:])
        if "error" in b:
            m.update(result="error", check="", seconds=0.0, detail=b["error"]); return m
        if not b["reached"]:
            m.update(result="unreached", check="", seconds=0.0,
                     detail="no composition of the sweep contains %s" % rel); return m
        timeout = args.timeout or 5 * b["seconds"] + 120
        shutil.rmtree(dump, ignore_errors=True)
        rc, output, secs = run_volren(b["args"] + ["--dump", dump], overlay, os.path.join(out, "logs", tag + ".log"), timeout)
        harness_ran = "volren permutations:" in output
        stable = binary_stamp() == b["stamp"]
        if not stable:
            say("  the binary changed while %s ran: again, against a new baseline" % tag)
            time.sleep(30); continue
        if rc is None or harness_ran: break
        time.sleep(30)  # the harness did not start: once more
    if not stable:
        m.update(result="error", check="", seconds=secs, detail="the binary was rebuilt during each of 4 tries")
        shutil.rmtree(dump, ignore_errors=True)
        return m
    new = [f for f in failures(output) if f not in b["failed"]]
    if rc is None:
        m.update(result="killed", check="timeout", detail="over %.0f s" % timeout)
    elif new:
        line = next(l for l in output.splitlines() if l.startswith("FAILED " + new[0][0]))
        m.update(result="killed", check=new[0][1], detail="%d new failures; first: %s" % (len(new), line[:300]))
    elif rc not in (0, 1) and harness_ran:
        m.update(result="killed", check="crash", detail="exit status %s" % rc)
    elif not harness_ran or rendered(output) is None:
        m.update(result="error", check="", detail="harness did not run (rc %s), see logs/%s.log" % (rc, tag))
    else:
        # Did the fault change any image? Identical first frames: equivalent on the sweep's scene
        # (no check could see it); different ones: the checks let the difference through.
        # Within 1e-6: float rounding (a changed shader compiles to differently fused arithmetic
        # elsewhere; two runs of one shader are bit-identical).
        compared, differ, worst = image_difference(b["dump"], dump)
        m.update(result="survived", check="", detail="%d rendered, no new failure; " % rendered(output) + (
            "images identical to the baseline's in all %d (equivalent on the sweep scene)" % compared if not differ else
            "images identical to the baseline's within %.2g (rounding) in all %d (equivalent on the sweep scene)"
            % (worst, compared) if worst <= 1e-6 else
            "images differ in %d of %d, by up to %.3g (not caught by the checks)" % (differ, compared, worst)))
    shutil.rmtree(dump, ignore_errors=True)
    m["seconds"] = secs
    say("  %-9s %-10s %s:%d %s  (%.0f s)" % (m["result"], m["check"] or "-", rel, m["line"], m["op"], secs))
    return m

# ---------------------------------------------------------------- main
selected = files()
if not selected: sys.exit("no shader files selected")
originals, mutants = {}, []
for rel in selected:
    with open(os.path.join(SHADERS, rel)) as f: originals[rel] = f.read()
    mutants += mutants_of(rel, originals[rel])
kinds = {rel: classify(rel)[0] for rel in selected}
say("volren mutation testing: %d files (%d implementations, %d includes), %d mutants, operators %s, "
    "max %d sites each, space %s, out %s" % (len(selected), sum(k == "impl" for k in kinds.values()),
    sum(k == "include" for k in kinds.values()), len(mutants), ",".join(ops), args.max_sites, args.space, out))

COLUMNS = ["file", "operator", "line", "original", "mutated", "result", "check", "seconds", "kind", "sweep", "detail"]
def write_report(ms):
    with open(os.path.join(out, "report.tsv"), "w") as f:
        f.write("\t".join(COLUMNS) + "\n")
        for m in ms:
            row = [m["file"], m["op"], str(m["line"]), m["original"], m["mutated"], m.get("result", ""), m.get("check", ""),
                   "%.1f" % m.get("seconds", 0.0), kinds.get(m["file"], "impl"), m.get("sweep", ""), m.get("detail", "")]
            f.write("\t".join(x.replace("\t", " ") for x in row) + "\n")

if args.dry_run:
    for m in mutants:
        m.update(result="planned", sweep=" ".join(sweep_args(m["file"])[1:]))
        say("  %s:%d %-9s %s" % (m["file"], m["line"], m["op"], m["mutated"][:110]))
    write_report(mutants)
    per = {}
    for m in mutants: per[m["sweep"]] = per.get(m["sweep"], 0) + 1
    for sweep, n in sorted(per.items()): say("  %4d mutants swept by: %s" % (n, sweep))
    say("%d mutants in %d files (a real run's summary estimates the time of all files from its seconds per mutant)"
        % (len(mutants), len({m["file"] for m in mutants})))
    sys.exit(0)

t_start = time.time()
sanity = None
if not args.no_sanity:
    for rel in selected:
        b = baseline(rel, originals[rel])
        if "error" not in b and b["reached"]:
            sanity = sanity_mutant(rel, originals[rel])
            if sanity: break
    if sanity:
        run_mutant(0, sanity, originals)
        if not (sanity["result"] == "killed" and sanity["check"] == "link"):
            write_report([sanity])
            sys.exit("SANITY FAILED: a syntax error in %s was %s%s: VOLREN_SHADER_PATH is not in effect (logs in %s)"
                     % (sanity["file"], sanity["result"], (" by " + sanity["check"]) if sanity.get("check") else "", out))
        say("sanity: a syntax error in %s is killed by link (%.0f s)" % (sanity["file"], sanity["seconds"]))

with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
    done = list(pool.map(lambda im: run_mutant(im[0] + 1, im[1], originals), enumerate(mutants)))
write_report(([sanity] if sanity else []) + done)

# ---------------------------------------------------------------- summary
lines = []
def summary(label, ms):
    ran = [m for m in ms if m["result"] in ("killed", "survived")]
    killed = [m for m in ran if m["result"] == "killed"]
    link = [m for m in killed if m["check"] == "link"]
    survived = [m for m in ran if m["result"] == "survived"]
    compiling = len(ran) - len(link)
    lines.append("%s: %d mutants, %d run: killed %d (by link %d, by other checks %d), survived %d; unreached %d, error %d"
                 % (label, len(ms), len(ran), len(killed), len(link), len(killed) - len(link), len(survived),
                    sum(m["result"] == "unreached" for m in ms), sum(m["result"] == "error" for m in ms)))
    if ran:
        lines.append("  score %.0f%% (killed/run), %.0f%% among compiling mutants (killed by a value check / compiling)"
                     % (100.0 * len(killed) / len(ran), 100.0 * (len(killed) - len(link)) / compiling if compiling else 0.0))
    same = sum("identical" in m.get("detail", "") for m in survived)
    if survived:
        lines.append("  survivors: %d with images identical to the baseline's (equivalent on the sweep scene), "
                     "%d with changed images that no check caught" % (same, len(survived) - same))
    by = {}
    for m in killed: by[m["check"]] = by.get(m["check"], 0) + 1
    if by: lines.append("  killing checks: " + ", ".join("%s %d" % kv for kv in sorted(by.items(), key=lambda kv: -kv[1])))
    return survived

surv_impl = summary("implementations", [m for m in done if kinds[m["file"]] == "impl"])
surv_inc = summary("include files", [m for m in done if kinds[m["file"]] == "include"])
secs = [m["seconds"] for m in done if m["result"] in ("killed", "survived")]
if secs:
    lines.append("seconds per mutant: mean %.1f, min %.1f, max %.1f; wall %.0f s (baselines included)"
                 % (sum(secs) / len(secs), min(secs), max(secs), time.time() - t_start))
if secs:
    everything = 0
    for rel in files(filtered=False):
        with open(os.path.join(SHADERS, rel)) as f: everything += len(mutants_of(rel, f.read()))
    lines.append("all %d shader files at --max-sites %d (these operators): %d mutants, ~%.1f h at --jobs 1 at this run's mean (plus a "
                 "baseline per file; unreached files cost nothing)" % (len(files(filtered=False)), args.max_sites, everything,
                                                                      everything * sum(secs) / len(secs) / 3600.0))
unreached = sorted({m["file"] for m in done if m["result"] == "unreached"})
if unreached: lines.append("not reached by the sweep: " + ", ".join(unreached))
if surv_impl or surv_inc:
    lines.append("survivors:")
    for m in surv_impl + surv_inc:
        lines.append("  %s:%d [%s] %s" % (m["file"], m["line"], m["op"], m["original"]))
        pad = " " * len("%s:%d" % (m["file"], m["line"]))
        lines.append("  %s   -> %s" % (pad, m["mutated"]))
        lines.append("  %s      %s" % (pad, m["detail"].split("; ", 1)[-1]))
rev = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip()
lines.append("binary: %s, modified %s (tree %s); report: %s" % (args.volren, time.strftime(
    "%Y-%m-%d %H:%M:%S", time.localtime(os.path.getmtime(args.volren))), rev or "?", os.path.join(out, "report.tsv")))
with open(os.path.join(out, "summary.txt"), "w") as f: f.write("\n".join(lines) + "\n")
say("\n".join(lines))
PY
