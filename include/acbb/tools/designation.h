/* acbb — a bearing from its designation: ISO 15 boundary dimensions (bore,
 * outside diameter, width) of the common ball-bearing series, and a scene
 * whose internal geometry (which catalogues do not publish) is estimated
 * by stated rules (src/scene/designation.c says which and why).
 *
 * Supported: angular contact 70xx, 72xx, 73xx, 718xx, 719xx with suffix
 * C (15 deg), AC (25 deg) or B (40 deg); deep groove 60xx, 62xx, 63xx,
 * 618xx, 619xx (nominal angle 0, CN clearance); bores 10..200 mm. */
#ifndef ACBB_DESIGNATION_H
#define ACBB_DESIGNATION_H

#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    char name[32];      /* canonical designation, "7014C", "6205" */
    int series;         /* designation series: 70 72 73 718 719 60 62 63 618 619 */
    int deep_groove;    /* 1: deep groove (angle 0), 0: angular contact */
    double angle;       /* nominal contact angle, rad (0 for deep groove) */
    double bore, outer_diameter, width; /* ISO 15 boundary dimensions, m */
} acbb_designation;

/* "7014C", "7205B", "71810AC", "6205": parsed and looked up. ACBB_EINVAL
 * with the reason (unknown series, bore not in the table, missing or
 * unexpected angle suffix). */
acbb_status acbb_designation_parse(const char *text, acbb_designation *d, acbb_error *err);

/* The explicit form: series as above, bore in mm, angle in degrees (0 or
 * negative for "none": required 0 for a deep-groove series, 5..45 for an
 * angular-contact one). */
acbb_status acbb_designation_make(int series, double bore_mm, double angle_deg,
                                  acbb_designation *d, acbb_error *err);

/* One estimated key: "section.key" and the rule that gave its value. */
typedef struct {
    const char *key;
    char rule[160];
} acbb_estimate;

/* The scene of designation d: engine defaults, the boundary dimensions,
 * and the estimated internal geometry. Writes up to `cap` notes, one per
 * estimated key; returns how many. The scene passes acbb_scene_validate. */
size_t acbb_designation_scene(const acbb_designation *d, acbb_scene *s, acbb_estimate *notes,
                              size_t cap);

#ifdef __cplusplus
}
#endif

#endif
