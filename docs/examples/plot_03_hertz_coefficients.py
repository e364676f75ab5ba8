"""
Exact Hertz coefficients
========================

The ellipticity and the dimensionless coefficients of a point contact, solved from the curvature
difference F(rho) for a whole array at once (see :doc:`/theory/hertz`). The two marked points are the
contacts of bearing 4-1006095, whose handbook values 0.63 and 0.852 are the exact 0.62834 and 0.85245
rounded.
"""

import matplotlib.pyplot as plt
import numpy as np

from bearinglab import hertz

f = np.linspace(0.0, 0.98, 400)
c = hertz.coefficients(f)
marked = hertz.coefficients([0.9287242, 0.7111269])
print("kappa  :", np.round(marked.ellipticity, 4))
print("delta* :", np.round(marked.delta_star, 5))

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8, 3.3), layout="constrained")
ax1.semilogy(f, c.ellipticity)
ax1.semilogy([0.9287242, 0.7111269], marked.ellipticity, "o")
ax1.set_xlabel("curvature difference F(ρ)")
ax1.set_ylabel("ellipticity κ = a/b")
for y, label in ((c.a_star, "a* (μ)"), (c.b_star, "b* (ν)"), (c.delta_star, "δ* (2K/πμ)")):
    ax2.plot(f, y, label=label)
ax2.set_xlabel("curvature difference F(ρ)")
ax2.legend()
plt.show()
