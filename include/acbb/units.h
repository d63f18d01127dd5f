/* acbb — the one place for constants and unit conversions (SI inside the
 * engine; presets and displays use mm, rpm, deg, deg C, MODEL.md section 0). */
#ifndef ACBB_UNITS_H
#define ACBB_UNITS_H

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_PI 3.14159265358979323846
#define ACBB_RPM (2.0 * ACBB_PI / 60.0)   /* rad/s per rpm */
#define ACBB_DEG (ACBB_PI / 180.0)        /* rad per degree */
#define ACBB_KELVIN 273.15                /* K at 0 deg C */

static inline double acbb_rpm_to_rads(double rpm) { return rpm * ACBB_RPM; }
static inline double acbb_rads_to_rpm(double w) { return w / ACBB_RPM; }
static inline double acbb_deg_to_rad(double d) { return d * ACBB_DEG; }
static inline double acbb_rad_to_deg(double r) { return r / ACBB_DEG; }

#ifdef __cplusplus
}
#endif

#endif
