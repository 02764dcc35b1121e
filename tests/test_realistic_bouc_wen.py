"""The Bouc-Wen stage of the realistic generator stays bounded under a fast input step.

HOLDOUT6's Bouc-Wen record (three band-limited drives joined end to end, with an input
jump where they meet) diverged to 1e8 in two of three seeds with four fixed RK4 substeps:
``beta |dv/dt| dt / 4`` reached 10, far past RK4's stability.  The stage now takes as many
substeps as that sample needs.
"""

import numpy as np

from realistic import mechanisms as me


def test_bouc_wen_stage_is_bounded_after_a_step_of_the_input():
    dt = 5e-4
    t = np.arange(4000) * dt
    v = 20.0 * np.sin(2 * np.pi * 3.0 * t)
    v[2000:] -= 35.0                       # a 35 V jump in one sample: |dv/dt| = 7e4 /s
    y = me.bouc_wen_stage(v, dt, fn=50.0, zeta=0.3)
    # a stable stage follows d v - h with |h| of the order of v: it stays within twice
    # the input's amplitude (it reached 1e8 with four fixed substeps)
    assert np.all(np.isfinite(y)) and np.max(np.abs(y)) < 2 * np.max(np.abs(v))


def test_slow_inputs_are_integrated_as_before():
    # below the stiff limit nothing changes: the substep count stays the one given
    dt = 5e-4
    t = np.arange(3000) * dt
    v = 40.0 * np.sin(2 * np.pi * 2.0 * t)
    a = me.bouc_wen_stage(v, dt, fn=60.0, zeta=0.3, substeps=4)
    b = me.bouc_wen_stage(v, dt, fn=60.0, zeta=0.3, substeps=8)
    # RK4 at 4 and 8 substeps of a smooth drive agree to well under the noise levels used
    np.testing.assert_allclose(a, b, atol=1e-6 * np.max(np.abs(a)))
