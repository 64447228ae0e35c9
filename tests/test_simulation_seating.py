"""The penalty penetration of a state (chaindrive.simulation.seating), the CAD pose's source.

Independent references: a pin put a known depth into a seat's arc (the depth is the
distance from the seat centre less the seat clearance r_s − r, ISO 606's seat of radius
0.505 d1), into a guide (the distance from the guide's line less the roller radius),
and the static assembly, whose pins all touch their profiles once moved back by it.
"""

from __future__ import annotations

import numpy as np
import pytest

from chaindrive.errors import InputError
from chaindrive.simulation import _kernel as K
from chaindrive.simulation import assemble, roller_example
from chaindrive.simulation import run as R
from chaindrive.simulation.seating import contact_penetration


def _tables():
    model = roller_example(links=30, teeth=11)
    par, wp, gd = R.kernel_arrays(model)
    return model, par, wp, gd


def test_pin_in_a_seat_arc_by_a_known_depth():
    model, par, wp, gd = _tables()
    theta = np.array([0.3, 0.0])
    e = np.array([np.cos(0.3), np.sin(0.3)])  # seat 0 of wheel 0 at its angle theta
    centre = wp[0, [K.W_CX, K.W_CY]]
    clearance = wp[0, K.W_RS] - par[K.P_RROLLER]  # r_s - r = 0.005 d1
    depth = 2e-6
    pos = np.array([centre + (wp[0, K.W_R] - clearance - depth) * e, [9.0, 9.0]])
    v = contact_penetration(pos, wp, theta, np.zeros(2), gd, par)
    # the penetration grows inwards along the seat radius: g n = -depth e
    np.testing.assert_allclose(v[0], -depth * e, atol=1e-12)
    assert np.all(v[1] == 0.0)  # far from everything
    # moved back by it, the pin touches the seat arc: no penetration left
    back = contact_penetration(pos - v, wp, theta, np.zeros(2), gd, par)
    assert np.abs(back).max() < 1e-15


def test_pin_on_a_guide_by_a_known_depth():
    _, par, wp, _ = _tables()
    gd = np.zeros((1, K.NGD))
    gd[0, :7] = [0.0, 5.0, 1.0, 0.0, 0.0, 1.0, 1.0]  # from (0, 5) along +x, the chain above (+y)
    gd[0, K.G_MU] = -1.0
    r = par[K.P_RROLLER]
    pos = np.array([[0.5, 5.0 + r - 3e-6], [0.5, 5.0 + r + 1e-6]])
    v = contact_penetration(pos, wp, np.zeros(2), np.zeros(2), gd, par)
    np.testing.assert_allclose(v[0], [0.0, -3e-6], atol=1e-12)  # grows towards the guide
    assert np.all(v[1] == 0.0)  # 1 um above it: no contact


def test_static_assembly_pins_touch_once_moved_back():
    st = assemble(roller_example(links=30, teeth=11))
    theta, slide = st.ws[:, K.S_THETA], st.ws[:, K.S_S]
    v = contact_penetration(st.pos, st.wp, theta, slide, st.gd, st.par)
    # independent: the contact forces k_c g n on the free, loaded wheel balance its load
    # torque (moment equilibrium of the static assembly), so the depths are the contact forces
    centre = st.wp[1, [K.W_CX, K.W_CY]]
    near = np.hypot(*(st.pos - centre).T) < st.wp[1, K.W_R] + 0.03
    q, f = st.pos[near] - centre, st.par[K.P_KC] * v[near]
    assert np.sum(q[:, 0] * f[:, 1] - q[:, 1] * f[:, 0]) == pytest.approx(-st.wp[1, K.W_TORQUE], rel=1e-6)
    depth = np.hypot(*v.T)
    assert 1e-6 < depth.max() < 1e-4  # regression: tens of micrometres at 200 N m on 11 teeth
    assert np.abs(contact_penetration(st.pos - v, st.wp, theta, slide, st.gd, st.par)).max() < 1e-15


def test_errors():
    _, par, wp, gd = _tables()
    with pytest.raises(InputError, match=r"pos must be an \(N, 2\)"):
        contact_penetration(np.zeros((3, 3)), wp, np.zeros(2), np.zeros(2), gd, par)
    with pytest.raises(InputError, match="theta must hold one value per wheel"):
        contact_penetration(np.zeros((3, 2)), wp, np.zeros(3), np.zeros(2), gd, par)
    with pytest.raises(InputError, match="slide must hold one value per wheel"):
        contact_penetration(np.zeros((3, 2)), wp, np.zeros(2), np.zeros(1), gd, par)
    with pytest.raises(InputError, match="pos"):
        contact_penetration(np.full((3, 2), np.nan), wp, np.zeros(2), np.zeros(2), gd, par)
