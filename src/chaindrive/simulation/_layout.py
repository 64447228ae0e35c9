"""Column layout of the simulation kernels' arrays (internal).

The wheel parameter (``wp``), wheel state (``ws``), parameter (``par``) and guide
(``gd``) columns shared by :mod:`._kernel`, :mod:`._implicit`, :mod:`._batched` and the
contact routines of :mod:`._contact` (one declaration; the layout is described in
:mod:`._kernel`).
"""

# wheel parameter columns
W_CX, W_CY, W_R, W_Z, W_RS, W_CPSI, W_SPSI, W_HTIP, W_INERTIA, W_MODE, W_OMEGA0, W_RAMP, \
    W_TORQUE, W_DAMP, W_SLIDE, W_DX, W_DY, W_SMASS, W_SK, W_SC, W_SF, W_NSEAT, W_DA, W_DB, \
    W_PLAIN, W_RE, W_CEA, W_CEB, W_TCA, W_TCB, W_DTA, W_DTB, W_MSYNC, W_MTK, W_MSK, W_RIPA, W_RIPW, \
    W_TSTOP, W_TDOWN, W_FCK, W_FCSN, W_FCC, W_FCJ = range(43)
NWP = 43
# time-varying drive: W_MSYNC, W_MTK, W_MSK synchronous speed [rad/s], breakdown torque [N m]
# and breakdown slip of a motor on the Kloss curve (MODE_MOTOR, reduced to the wheel);
# W_RIPA, W_RIPW relative amplitude and angular frequency [rad/s] of a torque ripple;
# W_TSTOP, W_TDOWN: from W_TSTOP [s] the motor is off (MODE_MOTOR) or the prescribed
# speed falls linearly to 0 over W_TDOWN [s] (MODE_SPEED); W_TSTOP <= 0: never
# W_FCJ > 0: the motor drives through a constant-fill fluid coupling (chaindrive.coupling):
# the motor rotor and coupling primary (inertia W_FCJ [kg m²], speed S_MOTOR) are their own
# degree of freedom; W_FCK = T_n (1 + c)/ω_n², W_FCSN = s_n, W_FCC = c (coupling_torque)
# W_RE > 0: ISO 606 convex flank arc of radius r_e (sprockets): its centre (W_CEA, W_CEB)
# and the tooth corner (W_TCA, W_TCB) in gap coordinates (a, |b|), the unit direction
# (W_DTA, W_DTB) from the flank centre to the corner; W_RE = 0: straight flank (pockets)
# W_PLAIN: 1 for a toothless idler (roller centres on the circle of radius W_R)
# W_NSEAT: number of seats per turn (z for a sprocket, 2z for a pocket wheel); W_DA, W_DB:
# central angles [rad] spanned by an even link (pins 2k, 2k+1) and an odd link when seated
# wheel state columns
S_THETA, S_OMEGA, S_S, S_SDOT, S_TORQUE, S_SFORCE, S_MOTOR, S_COUPLING = range(8)
NWS = 8
# S_MOTOR: speed of the motor behind a fluid coupling; S_COUPLING: the coupling's torque
# on the wheel in the last step (both 0 without a coupling)
# parameter vector
P_MASS, P_K, P_C, P_PITCH, P_RROLLER, P_KC, P_CC, P_MU, P_VEPS, P_GX, P_GY, P_DT, P_CGLOB, \
    P_KG, P_CG, P_DTREF, P_PITCH2, P_THETA, P_CSPAN = range(19)
NPAR = 19
# P_CSPAN: transverse span damping rate α [1/s] (SimulationModel.span_damping; every
# kernel, the batched ones per variant; 0: none and the earlier arithmetic unchanged)
# P_THETA: implicitness θ of the linearly implicit integrator (forces evaluated at
# x + θ h v⁺); unused by the explicit kernel
# P_PITCH: rest length of the even links (i = 0, 2, ...); P_PITCH2: of the odd links
# (equal for a roller chain; t + d and t - d for a round link chain)
# wheel modes
MODE_SPEED, MODE_FREE, MODE_LOCKED, MODE_MOTOR = 0, 1, 2, 3
# guide table columns: ax, ay, ux, uy, nx, ny, length, friction (< 0: the model's), material
# mass per pin [kg] scraped along the guide, its friction coefficient
G_MU, G_MM, G_MMU = 7, 8, 9
NGD = 10
