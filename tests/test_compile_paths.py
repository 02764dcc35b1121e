"""Which compiled kernels a call compiles (cold start, issue 13).

A first call compiles only the kernel copies it runs: the Python callers choose
the copy (`play_sum_kernel`, `inverse_kernel`, `mplay_sum_kernel`,
`step_kernel`, `loop_kernel`), and the specialised copies are cached on disk by
numba like any other kernel.  The subprocess test runs with a new, empty
``NUMBA_CACHE_DIR`` and records numba's compile events; it asserts which
functions were compiled, never how long that took (timings live in
benchmarks/bench_coldstart.py).
"""

import json
import os
import subprocess
import sys
import textwrap

import numpy as np
from hystcomp import _kernels as _k
from hystcomp import _loop_kernels as _lk
from hystcomp import MGPI, PI, StopPI
from hystcomp._block_specs import _NONE_SPEC, _spec
from hystcomp.envelopes import Atanh, Linear, Polynomial, Tanh

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

R = 0.5 * np.arange(1, 6)
P = 0.2 * np.ones(5)


def test_python_side_choice_of_kernel_copies():
    assert _k.play_sum_kernel(_k.IDENTITY) == (_k.pi_sum, True)
    assert _k.play_sum_kernel(_k.TANH) == (_k.play_sum_tanh, False)
    assert _k.play_sum_kernel(_k.POLYNOMIAL)[0] is _k.play_sum_general
    assert _k.mplay_sum_kernel(_k.TANH, _k.ATANH) is _k.mplay_sum_closed
    assert _k.mplay_sum_kernel(_k.TANH, _k.INVERSE_OF) is _k.mplay_sum_general
    cases = [
        (PI(R, P, p0=1.0), _lk.step_pi, _lk.step_exact_pi),
        (MGPI(R, P, 1.0, envelope=Linear(2.0)), _lk.step_pi, _lk.step_exact_closed),
        (MGPI(R, P, 1.0, envelope=Tanh(10.0, 0.2)), _lk.step_play_closed, _lk.step_play_closed),
        (MGPI(R, P, 1.0, envelope=Atanh(1.0, 0.05)), _lk.step_play_closed, _lk.step_exact_closed),
        (MGPI(R, P, 1.0, envelope=Polynomial([0.0, 1.0, 0.0, 0.01], interval=(-20.0, 20.0))), _lk.step_play_general,
         _lk.step_exact_general),
        (MGPI(R, P, 1.0, envelope_left=Tanh(10.0, 0.2), envelope_right=Tanh(10.0, 0.1)), _lk.step_mplay_closed,
         _lk.step_exact_other),
        (StopPI(R, P, p0=1.0), _lk.step_stop, _lk.step_exact_other),
    ]
    for model, forward, inverse in cases:
        spec = _spec(model, "hysteresis")
        assert _lk.step_kernel(spec[0], spec[1], spec[5], spec[7]) is forward, model
        ispec = _spec(model.exact_inverse(), "compensator")
        assert _lk.step_kernel(ispec[0], ispec[1], ispec[5], ispec[7]) is inverse, model
    assert _lk.step_kernel(_NONE_SPEC[0], 0, 0, 0) is _lk.step_none
    # one loop copy per pair of steps, kept; without a compensator the
    # hysteresis step fills the unused slot (the copy is shared)
    h = _spec(PI(R, P, p0=1.0), "hysteresis")
    c = _spec(PI(R, P, p0=1.0).exact_inverse(), "compensator")
    assert _lk.loop_kernel(h, c) is _lk.loop_kernel(h, c)
    assert _lk.loop_kernel(h, _NONE_SPEC) is _lk.loop_kernel(h, h)
    assert _lk.loop_kernel(h, c) is not _lk.loop_kernel(h, h)


def test_specialised_copies_release_the_gil_and_keep_their_names():
    for f in (_k.play_solve_pi, _k.play_solve_closed, _k.play_solve_general, _k.play_sum_closed,
              _k.play_sum_general, _lk.run_loop):
        assert f.targetoptions.get("nogil") is True, f
        assert f.py_func.__name__ == f.py_func.__qualname__  # its own cache entry
    assert _k.play_solve_pi.py_func.__name__ == "play_solve_pi"
    assert _k.play_solve_pi.__doc__  # documented like the other kernels


_SNIPPET = textwrap.dedent("""
    import json, sys
    import numpy as np
    from numba.core import event
    compiled = []

    class Listener(event.Listener):
        def on_start(self, ev):
            compiled.append(ev.data["dispatcher"].py_func.__qualname__)

        def on_end(self, ev):
            pass

    event.register("numba:compile", Listener())
    from hystcomp import PI
    from hystcomp.iosys import compensator_system, pid, piezo_stage
    from hystcomp.loops import build_loop, simulate_loop
    model = PI(0.5 * np.arange(1, 6), 0.2 * np.ones(5), p0=1.0)
    v = np.sin(np.linspace(0, 20, 2000))
    u = model.simulate(v)
    x = model.exact_inverse().simulate(u)
    assert np.max(np.abs(model.simulate(x) - u)) < 1e-9
    comp = compensator_system(model, method="exact", nominal_gain="auto", input_range=(-1.5, 1.5))
    loop = build_loop("feedback_compensated", model, piezo_stage(), controller=pid(0.05, 60.0, 0.0, 1e-4),
                      compensator=comp, dt=1e-4)
    t = np.arange(200) * 1e-4
    simulate_loop(loop, t, np.sin(2 * np.pi * 5 * t))
    print(json.dumps(compiled))
""")


def test_first_calls_compile_only_what_they_run_and_load_from_the_cache(tmp_path):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), PYTHONPATH=ROOT, MPLBACKEND="Agg")

    def run():
        out = subprocess.run([sys.executable, "-c", _SNIPPET], env=env, capture_output=True, text=True, cwd=ROOT,
                             timeout=600)
        assert out.returncode == 0, out.stderr[-3000:]
        return set(json.loads(out.stdout.strip().splitlines()[-1]))

    cold = run()
    assert {"pi_sum", "play_solve_pi", "run_loop__step_pi__step_exact_pi"} <= cold
    # the dispatching kernels and the copies of other envelope classes are not compiled
    for name in ("play_sum", "inverse_solve", "block_step", "run_loop", "play_solve_closed", "play_solve_general",
                 "play_sum_closed", "play_sum_general", "mplay_sum", "inverse_solve_other"):
        assert name not in cold, name
    # a new process on the filled cache compiles nothing (the specialised
    # copies are cached on disk like the other kernels)
    warm = run()
    assert warm == set(), sorted(warm)
