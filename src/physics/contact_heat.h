/* acbb — heat through a ball-race contact spot, one body, one contact
 * (MODEL.md 8.1 SP; docs/contact_heat.md).
 *
 * The resistance is the body's mean spot temperature rise over the heat
 * that enters it, K/W. Stationary: the isothermal elliptic spot on a half
 * space (Yovanovich [Y]). Moving: the body's surface passes through the
 * spot at speed v along the semi-axis b (the rolling direction), so the
 * heat has only the passage time to spread: Archard's (1959) high-speed
 * mean temperature of a uniform source, combined with the stationary one
 * in the form of Tian & Kennedy (1994), valid at every Peclet number.
 * Pure functions. */
#ifndef ACBB_CONTACT_HEAT_H
#define ACBB_CONTACT_HEAT_H

/* Stationary spot, semi-axes a, b (m, either order), conductivity k
 * (W/(m K)): K(e) / (2 pi k a) with a the larger semi-axis. a or b not
 * > 0: +inf (no contact; the caller caps it). */
double acbb_spot_r_stationary(double a, double b, double k);

/* High-speed limit alone: a = semi-axis across the rolling direction, b =
 * along it (m), k, diffusivity kappa = k / (rho c_p) (m^2/s), surface
 * speed v (m/s): C_inf sqrt(kappa / (v b)) / (k a), C_inf = 0.30995.
 * v or b not > 0: +inf (no moving-source limit). */
double acbb_spot_r_fast(double a, double b, double k, double kappa, double v);

/* Moving source at every Peclet number: conductances add in quadrature,
 * R = (R_stat^-2 + R_fast^-2)^(-1/2). Tends to acbb_spot_r_stationary as
 * v -> 0 (exactly R_stat at v = 0) and to acbb_spot_r_fast (~Pe^-1/2) at
 * high Pe. */
double acbb_spot_r_moving(double a, double b, double k, double kappa, double v);

/* The body's Peclet number v b / (2 kappa) (Jaeger's, with b the
 * half-width along the motion). */
double acbb_spot_peclet(double b, double kappa, double v);

/* C_inf = 8 sqrt(2) Gamma(7/4) / (3 pi^2 Gamma(9/4)). */
double acbb_spot_c_fast(void);

#endif
