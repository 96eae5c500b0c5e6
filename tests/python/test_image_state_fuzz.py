"""shadelab.Image.__setstate__ under hostile states: a real image's pickle state (__getstate__), then tampered with
at random (fixed seed): negative, zero and huge sizes, wrong channel counts, short and long buffers, wrong types,
tuples of the wrong length. Each state must be refused with ValueError or TypeError, or make an image that then
behaves (repr, sizes, np.asarray, to_uint8, to_png, coverage, pickling again). Never a signal or an abort: the
states run in a subprocess per batch, whose return code the test checks, and a negative control shows that the
check sees an abort."""

import os
import pickle
import random
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import shadelab

ALLOWED = ("ValueError", "TypeError")
CASES, BATCH = 360, 60

# The child: reads the pickled list of states on stdin; for each, says which case it starts (so that a death names
# its case), applies the state as pickle does (two ways), uses the image, and prints the outcome.
CHILD = textwrap.dedent(
    """
    import copyreg, io, pickle, sys
    import numpy as np
    import shadelab

    class Tampering(pickle.Pickler):
        # Pickles an Image with `state` for its state: pickle.loads then calls Image.__setstate__ with it.
        def __init__(self, file, state):
            super().__init__(file, protocol=2)
            self.state = state

        def reducer_override(self, obj):
            if type(obj) is shadelab.Image:
                return (copyreg.__newobj__, (shadelab.Image,), self.state)
            return NotImplemented

    def through_pickle(state):
        f = io.BytesIO()
        Tampering(f, state).dump(shadelab.Image.from_array(np.zeros((1, 1, 3), dtype=np.uint8)))
        return pickle.loads(f.getvalue())

    def after_use():
        pass  # the negative controls replace this

    def use(image):
        repr(image)
        image.size, image.shape, image.width, image.height, image.encoding, image.source, image.timings
        np.asarray(image).sum()
        image.to_uint8().sum()
        image.to_png()
        coverage = image.coverage
        if coverage is not None:
            coverage.sum()
        pickle.loads(pickle.dumps(image))
        after_use()

    cases = pickle.load(sys.stdin.buffer)
    for i, state in enumerate(cases):
        print("start", i, flush=True)
        try:
            if i % 2:
                image = through_pickle(state)
            else:
                image = shadelab.Image.__new__(shadelab.Image)
                image.__setstate__(state)
            use(image)
            outcome = "ok"
        except Exception as e:
            outcome = type(e).__name__ + ": " + str(e)[:200].replace("\\n", " ")
        print("outcome", i, outcome, flush=True)
    """
)


def run_batch(cases, child=CHILD):
    """Runs the states in one subprocess; returns the problems found (empty: every state ended as allowed)."""
    p = subprocess.run([sys.executable, "-c", child], input=pickle.dumps(cases), capture_output=True,
                       env=os.environ.copy(), timeout=600)
    outcomes, started = {}, None
    for line in p.stdout.decode(errors="replace").splitlines():
        kind, _, rest = line.partition(" ")
        index, _, outcome = rest.partition(" ")
        if kind == "start":
            started = int(index)
        elif kind == "outcome":
            outcomes[int(index)] = outcome
    problems = []
    if p.returncode != 0:
        how = f"signal {-p.returncode}" if p.returncode < 0 else f"exit code {p.returncode}"
        case = cases[started] if started is not None and started < len(cases) else None
        problems.append(f"the subprocess ended with {how} during case {started}: state {describe(case)}; "
                        f"stderr: {p.stderr.decode(errors='replace')[-1500:]}")
    for i, outcome in sorted(outcomes.items()):
        if outcome != "ok" and not outcome.startswith(tuple(k + ":" for k in ALLOWED)):
            problems.append(f"case {i}: {outcome} (expected {' or '.join(ALLOWED)}, or success): state "
                            f"{describe(cases[i])}")
    if p.returncode == 0 and len(outcomes) != len(cases):
        problems.append(f"the subprocess reported {len(outcomes)} of {len(cases)} cases")
    return problems


def describe(state):
    """A state in a line: bytes by their length, long strings cut."""
    def one(v):
        if isinstance(v, (bytes, bytearray, memoryview)):
            return f"<{type(v).__name__} of {len(v)}>"
        if isinstance(v, str) and len(v) > 40:
            return f"<str of {len(v)}>"
        return repr(v)
    if isinstance(state, tuple):
        return "(" + ", ".join(one(v) for v in state) + ")"
    return one(state)


HOSTILE_INTS = [0, -1, 1, 2, 3, 4, 5, -2**31, 2**31 - 1, 2**31, 2**32, 2**32 + 1, 2**63 - 1, 2**63, -2**63, 2**64,
                2**64 + 3, 10**30, 65536, 46341, 1 << 20]
HOSTILE_FLOATS = [float("nan"), float("inf"), -float("inf"), -0.0, 1e308, -1.0, 5e-324]
HOSTILE_STRS = ["", "srgb", "linear", "SRGB", "bogus", "\x00", "é", "x" * 100000]
ANYTHING = [None, True, 1.5, "3", b"", bytearray(b"\x00" * 12), [1, 2, 3], (1,), {"a": 1}, object, 2**70, -7,
            float("nan"), np.int64(4), np.float32(2.0)]


def buffer_variants(b, rng):
    n = len(b)
    return [b"", b[: n // 2], b[:-1], b + b"\x00", b + b"\x00" * 4, b * 2, b[: n - n % 4 - 4] if n >= 8 else b"",
            bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64))), bytearray(b), b.decode("latin-1")]


def tamper(base, rng):
    """One hostile state made from the real one."""
    state = list(base)
    kind = rng.randrange(10)
    if kind == 0:  # the wrong number of items, or not a tuple at all
        return rng.choice([tuple(state[:-1]), tuple(state + [0]), (), tuple(state[:3]), state, None, 7,
                           b"".join(v for v in state if isinstance(v, bytes)), {"state": tuple(state)}])
    if kind == 1 and all(isinstance(v, int) for v in state[:3]):
        # A size whose buffers match it exactly, up to sizes nobody should allocate from a pickle.
        w, h = rng.choice([(0, 0), (0, 5), (5, 0), (-1, -1), (-2, -3), (1, 1), (3, 2), (2**16, 2**16),
                           (2**31 - 1, 1), (46341, 46341), (-(2**31), -1)])
        c = rng.choice([3, 4, 1, 0, -3])
        state[0], state[1], state[2] = w, h, c
        pixels = max(w * h, 0)
        if pixels <= 1024:
            for i, v in enumerate(state):
                if isinstance(v, bytes) and i > 2:
                    state[i] = bytes(pixels * (max(c, 0) if i == 3 else 4 * (4 if i == 4 else 1)))
        return tuple(state)
    # Otherwise one to three items replaced with something of their type, or of any type.
    for _ in range(rng.randrange(1, 4)):
        i = rng.randrange(len(state))
        v = base[i]
        if rng.random() < 0.2:
            state[i] = rng.choice(ANYTHING)
        elif isinstance(v, bool) or isinstance(v, int):
            state[i] = rng.choice(HOSTILE_INTS)
        elif isinstance(v, float):
            state[i] = rng.choice(HOSTILE_FLOATS + HOSTILE_INTS[:4])
        elif isinstance(v, bytes):
            state[i] = rng.choice(buffer_variants(v, rng))
        elif isinstance(v, str):
            state[i] = rng.choice(HOSTILE_STRS)
        else:
            state[i] = rng.choice(ANYTHING)
    return tuple(state)


@pytest.fixture(scope="module")
def real_states(source_dir):
    """Pickle states of real images: 8-bit RGB and RGBA arrays, and a traced render with coverage."""
    rgb = shadelab.Image.from_array(np.arange(4 * 5 * 3, dtype=np.uint8).reshape(4, 5, 3))
    rgba = shadelab.Image.from_array(np.full((3, 2, 4), 0.25, dtype=np.float32))
    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")
    traced = shadelab.render(scene, (8, 6), renderer="trace", coverage=True)
    states = [image.__getstate__() for image in (rgb, rgba, traced)]
    for image, state in zip((rgb, rgba, traced), states):
        # The untampered states work: the fuzzing starts from states that load.
        back = pickle.loads(pickle.dumps(image))
        assert back.size == image.size and np.array_equal(np.asarray(back), np.asarray(image))
        assert isinstance(state, tuple)
    return states


def test_tampered_states_raise_value_or_type_error(real_states):
    rng = random.Random(25)
    cases = [tamper(rng.choice(real_states), rng) for _ in range(CASES)]
    problems = []
    for start in range(0, len(cases), BATCH):
        problems += run_batch(cases[start:start + BATCH])
    assert not problems, f"{len(problems)} problems, the first ones:\n" + "\n".join(problems[:10])


def test_untampered_states_pass_the_same_check(real_states):
    assert run_batch(list(real_states)) == []


def test_negative_control_an_abort_is_detected(real_states):
    child = CHILD.replace("pass  # the negative controls replace this", "import os; os.abort()")
    assert child != CHILD
    problems = run_batch(list(real_states), child=child)
    assert problems and "signal" in problems[0] and "case 0" in problems[0], problems


def test_negative_control_another_exception_is_detected(real_states):
    child = CHILD.replace("pass  # the negative controls replace this", "raise RuntimeError('not allowed')")
    assert child != CHILD
    problems = run_batch(list(real_states), child=child)
    assert len(problems) == len(real_states) and "RuntimeError" in problems[0], problems
