"""The coefficients of one step of an additive Runge-Kutta method: Kennedy and Carpenter's
ARK4(3)6L[2]SA, six stages, fourth order with an embedded third-order solution, its
implicit part L-stable and stiffly accurate.

An additive method integrates ``y' = f_E(y) + f_I(y)``, the non-stiff part ``f_E``
explicitly and the stiff part ``f_I`` by a diagonally implicit method, both with the same
stages. Here the stiff part is linear, ``f_I(y) = D (y - y_n)`` with a matrix ``D`` fixed
over the step, and the explicit part the rest, ``f_E = f - f_I``: the splitting is exact
whatever ``D`` is, so the method keeps its order with any matrix; ``D`` only decides which
of the right-hand side's rates the explicit part still has to resolve. Stage ``i`` solves
``(I - h gamma D) z_i = h sum_{j<i} (a^E_ij k^E_j + a^I_ij k^I_j)`` for
``z_i = Y_i - y_n``, with ``k^I_j = D z_j`` and ``k^E_j = f(Y_j) - k^I_j``; both parts
share their weights ``b`` (and ``b-hat``), so the step is ``y_n + h sum_i b_i f(Y_i)`` and
its error estimate ``h sum_i (b_i - b-hat_i) f(Y_i)``.

References
----------
.. [1] C. A. Kennedy and M. H. Carpenter, Additive Runge-Kutta schemes for
   convection-diffusion-reaction equations, Applied Numerical Mathematics 44 (2003)
   139-181, doi:10.1016/S0168-9274(02)00138-1 (ARK4(3)6L[2]SA: its Table 5's coefficients).
.. [2] E. Hairer and G. Wanner, Solving Ordinary Differential Equations II, 2nd ed.,
   Springer (1996), doi:10.1007/978-3-642-05221-7, IV.6 (diagonally implicit methods).
"""
from __future__ import annotations

import numpy as np

STAGES = 6
#: The implicit part's diagonal.
GAMMA = 0.25
#: The explicit part's stage coefficients ``a^E``.
EXPLICIT = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [13861 / 62500, 6889 / 62500, 0.0, 0.0, 0.0, 0.0],
    [-116923316275 / 2393684061468, -2731218467317 / 15368042101831,
     9408046702089 / 11113171139209, 0.0, 0.0, 0.0],
    [-451086348788 / 2902428689909, -2682348792572 / 7519795681897,
     12662868775082 / 11960479115383, 3355817975965 / 11060851509271, 0.0, 0.0],
    [647845179188 / 3216320057751, 73281519250 / 8382639484533,
     552539513391 / 3454668386233, 3354512671639 / 8306763924573, 4040 / 17871, 0.0]])
#: The implicit part's ``a^I`` below its diagonal (the diagonal is ``GAMMA`` but for the
#: first, explicit, stage).
IMPLICIT = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 4, 0.0, 0.0, 0.0, 0.0, 0.0],
    [8611 / 62500, -1743 / 31250, 0.0, 0.0, 0.0, 0.0],
    [5012029 / 34652500, -654441 / 2922500, 174375 / 388108, 0.0, 0.0, 0.0],
    [15267082809 / 155376265600, -71443401 / 120774400, 730878875 / 902184768,
     2285395 / 8070912, 0.0, 0.0],
    [82889 / 524892, 0.0, 15625 / 83664, 69875 / 102672, -2260 / 8211, 0.0]])
#: The weights of the fourth-order solution (the implicit part's last row: stiffly
#: accurate) and of the embedded third-order one, shared by both parts.
WEIGHTS = np.array([82889 / 524892, 0.0, 15625 / 83664, 69875 / 102672, -2260 / 8211,
                    1 / 4])
EMBEDDED = np.array([4586570599 / 29645900160, 0.0, 178811875 / 945068544,
                     814220225 / 1159782912, -3700637 / 11593932, 61727 / 225920])
ERROR = WEIGHTS - EMBEDDED
