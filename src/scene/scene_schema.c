/* acbb — scene schema: the table of preset keys, defaults, field access,
 * number formatting and ranges (scene_internal.h says how the parts share
 * the table).
 *
 * Unit conversion: value_SI = value_preset * scale. No key needs an offset:
 * temperatures stay in degrees Celsius inside a Scene (see scene.h).
 *
 * Locale: numbers are read and written in the "C" locale whatever the host
 * program set (base/c_locale.h), so a preset reads and saves the same under
 * de_DE. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acbb/limits.h"
#include "acbb/tools/set.h"
#include "acbb/units.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"
#include "c_locale.h"
/* Enum fields are read and written through an int (memcpy, no aliasing). */
_Static_assert(sizeof(acbb_model_level) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_geom_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_race_control) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_hertz_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_visc_model) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_traction_model) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_loss_form) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_hyst_axis) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_roll_hyst) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_physics_profile) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_network_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_preload_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_set_arrangement) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_tilt_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_thermal_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_bc_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_fidelity_preset) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_lub_method) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_oil_grade) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_contact_model) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_rear_support) == sizeof(int), "enum size");

/* Enum choices, in the order of the C enum values in scene.h. */
static const char *const k_model[] = {"static", "quasi-static", "quasi-dynamic", "dynamic", NULL};
static const char *const k_hertz[] = {"exact", "bh77", "hb83", NULL};
static const char *const k_clean_seed[] = {"clean", "seed", NULL};
static const char *const k_race[] = {"outer", "inner", "equal", "auto", NULL};
static const char *const k_hyst[] = {"major", "minor", NULL};
static const char *const k_roll_hyst[] = {"seed", "johnson", NULL};
static const char *const k_profile[] = {"seed", "reference", NULL};
static const char *const k_visc[] = {"roelands", "barus", "const", NULL};
static const char *const k_traction[] = {"eyring-cap", "bair-winer", NULL};
static const char *const k_preload[] = {"force", "displacement", NULL};
static const char *const k_tilt[] = {"auto", "free", "held", NULL};
static const char *const k_network[] = {"46", "7", NULL};
static const char *const k_contact[] = {"stationary", "moving", NULL};
static const char *const k_thermal_mode[] = {"transient", "steady", NULL};
static const char *const k_bc[] = {"fixed", "derived", "convective", NULL};
static const char *const k_fid_preset[] = {"custom", "fast", "balanced", "reference", NULL};
static const char *const k_lub_method[] = {"oil-air", "oil-jet", "oil-bath", "grease", NULL};
static const char *const k_grade[] = {"custom", "VG2", "VG3", "VG5", "VG7", "VG10", "VG15", "VG22",
    "VG32", "VG46", "VG68", "VG100", "VG150", "VG220", "VG320", "VG460", "VG680", "VG1000",
    "VG1500", NULL};
static const char *const k_rear_support[] = {"fixed", "spring", "floating", NULL};

#define LO_OPEN(ends) ((ends) == OC || (ends) == OO)
#define HI_OPEN(ends) ((ends) == CO || (ends) == OO)
#define REAL(sec, key, unit, member, scale, def, ends, lo, hi, help) \
    REALP(sec, key, unit, member, scale, def, ends, lo, hi, help, 0, 0, NULL)
/* A REAL key that is an uncertain input: plausible range plo..phi (preset
 * units) and its source (scene.h, acbb_field_info). */
#define REALP(sec, key, unit, member, scale, def, ends, lo, hi, help, plo, phi, psrc) \
    {{sec, key, ACBB_FIELD_REAL, unit, lo, hi, NULL, help, LO_OPEN(ends), HI_OPEN(ends), \
      plo, phi, psrc}, offsetof(acbb_scene, member), scale, def, ends}
#define INT(sec, key, member, def, lo, hi, help) \
    {{sec, key, ACBB_FIELD_INT, "", lo, hi, NULL, help, false, false, 0, 0, NULL}, \
     offsetof(acbb_scene, member), 1.0, def, CC}
#define BOOL(sec, key, member, def, help) \
    {{sec, key, ACBB_FIELD_BOOL, "", 0, 1, NULL, help, false, false, 0, 0, NULL}, \
     offsetof(acbb_scene, member), 1.0, def, CC}
#define ENUM(sec, key, member, choices, def, help) \
    ENUMP(sec, key, member, choices, def, help, 0, 0, NULL)
/* An ENUM key that is a two-level uncertain input: choices plo and phi. */
#define ENUMP(sec, key, member, choices, def, help, plo, phi, psrc) \
    {{sec, key, ACBB_FIELD_ENUM, "", 0, \
      (double)(sizeof(choices) / sizeof(choices[0]) - 2), choices, help, false, false, \
      plo, phi, psrc}, offsetof(acbb_scene, member), 1.0, def, CC}

/* Six keys per part of [materials]. */
#define MATERIAL(part, vE, vnu, vrho, vcp, vk, vchi, chi_lo, chi_hi, chi_src) \
    REAL("materials", #part "_E_GPa", "GPa", part.E, 1e9, vE, OC, 0, 1000, \
         "Young's modulus of the " #part), \
    REAL("materials", #part "_poisson", "", part.nu, 1.0, vnu, OO, 0, 0.5, \
         "Poisson ratio of the " #part), \
    REAL("materials", #part "_density_kg_m3", "kg/m^3", part.rho, 1.0, vrho, OC, 0, 30000, \
         "density of the " #part), \
    REAL("materials", #part "_cp_J_kgK", "J/(kg K)", part.cp, 1.0, vcp, OC, 0, 10000, \
         "specific heat of the " #part), \
    REAL("materials", #part "_k_W_mK", "W/(m K)", part.k, 1.0, vk, OC, 0, 1000, \
         "thermal conductivity of the " #part), \
    REALP("materials", #part "_expansion_ppm_K", "ppm/K", part.chi, 1e-6, vchi, CC, 0, 100, \
          "linear thermal expansion coefficient of the " #part, chi_lo, chi_hi, chi_src)

/* Three keys per cooled face of [surroundings] (MODEL.md 8.1, 13); the
 * seed holds each face at ambient. */
#define FACE_BC(name, member, what, h_def, h_lo, h_hi, h_src) \
    ENUMP("surroundings", name, member.kind, k_bc, ACBB_BC_DERIVED, \
          what ": fixed at the coolant T, convective, or derived (fixed on the seed rig only)", \
          ACBB_BC_DERIVED, ACBB_BC_CONVECTIVE, \
          "docs/physics.md section 13: [S] holds it at ambient; convective at the h below"), \
    REALP("surroundings", name "_h_W_m2K", "W/(m^2 K)", member.h, 1.0, h_def, OC, 0, 1e10, \
          "film coefficient of a convective " what, h_lo, h_hi, h_src), \
    REAL("surroundings", name "_coolant_dT_K", "K", member.dT, 1.0, 0, CC, -100, 200, \
         what " coolant temperature minus operating.ambient_C (0: at ambient)")

/* The schema. Defaults: MODEL.md section 10 (the 7008C case of the seed). */
const acbb_sfield acbb_sf_table[] = {
    REAL("bearing", "pitch_diameter_mm", "mm", pitch_diameter, 1e-3, 54, OC, 0, 2000,
         "pitch diameter d_m (docs/physics.md section 1)"),
    REAL("bearing", "ball_diameter_mm", "mm", ball_diameter, 1e-3, 6.35, OC, 0, 100,
         "ball diameter D"),
    INT("bearing", "n_balls", n_balls, 21, 3, 64, "number of balls Z (the engine holds up to 64)"),
    REAL("bearing", "inner_groove_radius_mm", "mm", inner_groove_radius, 1e-3, 3.43, OC, 0, 100,
         "inner groove radius lambda_i (needs lambda_i / D >= 0.505)"),
    REAL("bearing", "outer_groove_radius_mm", "mm", outer_groove_radius, 1e-3, 3.43, OC, 0, 100,
         "outer groove radius lambda_o (needs lambda_o / D >= 0.505)"),
    REAL("bearing", "contact_angle_deg", "deg", contact_angle0, ACBB_DEG, 15, CC, 0, 45,
         "free contact angle alpha0; sets P_d unless clearance_um > 0; 0 = deep groove "
         "(docs/physics.md section 1)"),
    REAL("bearing", "clearance_um", "um", clearance, 1e-6, 0, CC, 0, 1000,
         "diametral clearance P_d; 0 = from contact_angle_deg; > 0 gives the free angle "
         "(contact_angle_deg 0 or equal to it)"),
    REAL("bearing", "bore_mm", "mm", bore, 1e-3, 40, OC, 0, 2000,
         "bearing bore (inside diameter of the inner ring)"),
    REAL("bearing", "outer_diameter_mm", "mm", outer_diameter, 1e-3, 68, OC, 0, 2000,
         "bearing outside diameter"),
    REAL("bearing", "width_mm", "mm", width, 1e-3, 15, OC, 0, 500, "ring width B_w"),
    REAL("bearing", "cage_width_mm", "mm", cage_width, 1e-3, 10.1, OC, 0, 500, "cage width W_c"),
    REAL("bearing", "cage_diameter_mm", "mm", cage_diameter, 1e-3, 57.7, OC, 0, 2000,
         "cage outside (guiding) diameter d_c"),
    REAL("bearing", "inner_land_diameter_mm", "mm", inner_land_diameter, 1e-3, 49.9, OC, 0, 2000,
         "inner ring land diameter d_1"),
    REAL("bearing", "outer_land_diameter_mm", "mm", outer_land_diameter, 1e-3, 58.1, OC, 0, 2000,
         "outer ring land diameter d_2"),
    REAL("bearing", "roughness_race_um", "um", roughness_race, 1e-6, 0.34, CC, 0, 10,
         "RMS roughness of the raceways"),
    REAL("bearing", "roughness_ball_um", "um", roughness_ball, 1e-6, 0.10, CC, 0, 10,
         "RMS roughness of the balls"),

    MATERIAL(ball, 207, 0.3, 7810, 450, 40.1, 12.5, 11.5, 13,
             "docs/physics.md section 10 ASSUMED 12.5 (52100 handbook 11.5-13)"),
    MATERIAL(ring, 207, 0.3, 7810, 450, 40.1, 12.5, 11.5, 13,
             "docs/physics.md section 10 ASSUMED 12.5 (52100 handbook 11.5-13)"),
    MATERIAL(shaft, 212, 0.298, 7860, 485, 42.4, 11.5, 10.8, 12.5,
             "docs/physics.md section 10 ASSUMED 11.5 (medium-C steel 10.8-12.5)"),
    MATERIAL(housing, 143, 0.27, 7300, 510, 45.0, 10.5, 9, 12,
             "docs/physics.md section 10 ASSUMED 10.5 (grey iron 9-12)"),
    /* The cage's E, nu and chi enter nothing (no cage mechanics, MODEL.md 7
     * expands balls, rings, shaft and housing only): no plausible range, so
     * sensitivity and report do not vary a dead input; a changed value is
     * named by acbb_scene_inactive_effects. */
    MATERIAL(cage, 206, 0.254, 7830, 460, 44.0, 11.7, 0, 0, NULL),

    REAL("lubricant", "oil_density_kg_m3", "kg/m^3", oil_density, 1.0, 876, OC, 0, 2000,
         "oil density at 20 C"),
    REAL("lubricant", "oil_nu40_mm2_s", "mm^2/s", oil_nu40, 1e-6, 30, CC, 1, 10000,
         "oil kinematic viscosity at 40 C (Walther law, docs/physics.md section 5)"),
    REALP("lubricant", "oil_nu100_mm2_s", "mm^2/s", oil_nu100, 1e-6, 5.3, CC, 1, 10000,
          "oil kinematic viscosity at 100 C (Walther law)", 5.0, 5.8,
          "docs/physics.md section 5 ASSUMED 5.3 (ISO VG 32, VI 90-120)"),
    REAL("lubricant", "oil_eta_const_Pa_s", "Pa s", oil_eta_const, 1.0, 0.2, OC, 0, 100,
         "oil viscosity used when viscosity_model = const"),
    REALP("lubricant", "oil_alpha_pv_per_GPa", "1/GPa", oil_alpha_pv, 1e-9, 20, CC, 0, 100,
          "pressure-viscosity coefficient alpha_pv", 15, 25,
          "docs/physics.md section 5 ASSUMED, mineral oil 1.5-2.5e-8 1/Pa"),
    REALP("lubricant", "oil_k_W_mK", "W/(m K)", oil_k, 1.0, 0.13, OC, 0, 10,
          "oil thermal conductivity", 0.11, 0.15,
          "docs/physics.md section 5 ASSUMED 0.13 (mineral oils 0.11-0.15)"),
    REALP("lubricant", "oil_cp_J_kgK", "J/(kg K)", oil_cp, 1.0, 1950, OC, 0, 10000,
          "oil specific heat", 1800, 2100,
          "docs/physics.md section 10 ASSUMED 1950 (mineral oils 1.8-2.1 kJ/kgK)"),
    REAL("lubricant", "air_eta_Pa_s", "Pa s", air_eta, 1.0, 2e-5, OC, 0, 1e-3, "air viscosity"),
    REAL("lubricant", "air_density_kg_m3", "kg/m^3", air_density, 1.0, 1.128, OC, 0, 100,
         "air density"),
    REAL("lubricant", "air_k_W_mK", "W/(m K)", air_k, 1.0, 0.027, OC, 0, 10,
         "air thermal conductivity"),
    REAL("lubricant", "air_cp_J_kgK", "J/(kg K)", air_cp, 1.0, 1007, OC, 0, 10000,
         "air specific heat"),
    REAL("lubricant", "air_prandtl", "", air_pr, 1.0, 0.71, OC, 0, 10, "air Prandtl number"),
    REALP("lubricant", "mixture_k_W_mK", "W/(m K)", mix_k, 1.0, 0.04, OC, 0, 10,
          "oil-air mixture conductivity k_d", 0.02, 0.06,
          "docs/physics.md section 8.1 interpretation of [S] T2: +-50 %"),
    REAL("lubricant", "air_flow_L_min", "L/min", q_air, 1e-3 / 60.0, 60, CC, 0, 10000,
         "oil-air lubrication: air flow"),
    REAL("lubricant", "oil_flow_ml_h", "ml/h", q_oil, 1e-6 / 3600.0, 0.4, CC, 0, 100000,
         "oil-air lubrication: oil flow"),
    REALP("lubricant", "boundary_friction", "", mu_bd, 1.0, 0.10, CC, 0, 1,
          "boundary (asperity) friction coefficient mu_bd", 0.08, 0.13,
          "docs/physics.md section 5 ASSUMED 0.08-0.13"),
    REALP("lubricant", "limiting_shear_ratio", "", lambda_lim, 1.0, 0.07, OC, 0, 1,
          "limiting shear stress / pressure Lambda_L", 0.05, 0.1,
          "docs/physics.md section 5 ASSUMED 0.05-0.1"),
    REALP("lubricant", "eyring_stress_MPa", "MPa", tau_eyring, 1e6, 5, OC, 0, 1000,
          "Eyring stress tau_E", 2.5, 10,
          "docs/physics.md section 5 ASSUMED 5 MPa, no range quoted: x/2 to x2"),
    REALP("lubricant", "hysteresis_loss", "", hysteresis, 1.0, 0.007, CC, 0, 1,
          "elastic hysteresis loss coefficient epsilon", 0.005, 0.01,
          "docs/physics.md section 6 UNSURE, [HK]/[J] 0.005-0.01"),
    REALP("lubricant", "drag_coefficient", "", drag_cd, 1.0, 0.45, CC, 0, 10,
          "drag coefficient C_D of a ball in the oil-air mixture", 0.38, 0.5,
          "docs/physics.md section 6 ASSUMED, sphere curve 0.38-0.5 for 1e3<Re<2e5"),
    ENUM("lubricant", "viscosity_model", visc, k_visc, ACBB_VISC_ROELANDS,
         "pressure-viscosity law (const: oil_eta_const_Pa_s everywhere)"),
    ENUM("lubricant", "traction_model", traction, k_traction, ACBB_TRACTION_EYRING_CAP,
         "film traction law (docs/physics.md section 5)"),
    ENUM("lubricant", "method", lub_method, k_lub_method, ACBB_LUB_OIL_AIR,
         "lubrication method (docs/physics.md section 16): starvation, drag and churning medium"),
    ENUM("lubricant", "grade", oil_grade, k_grade, ACBB_GRADE_CUSTOM,
         "ISO 3448 viscosity grade (docs/physics.md section 16)"),
    REAL("lubricant", "viscosity_index", "", oil_vi, 1.0, 100, CC, 0, 400,
         "viscosity index (ASTM D2270) that gives a graded oil's nu100"),
    REAL("lubricant", "jet_speed_m_s", "m/s", jet_speed, 1.0, 10, CC, 0, 300,
         "oil-jet exit speed (method = oil-jet; oil_flow_ml_h is the jet flow)"),
    REAL("lubricant", "bath_level_mm", "mm", bath_level, 1e-3, 0, CC, 0, 10000,
         "oil-bath level above the lowest point of the outer raceway (method = oil-bath)"),
    REAL("lubricant", "grease_base_oil_nu40_mm2_s", "mm^2/s", grease_nu40, 1e-6, 0, CC, 0, 10000,
         "grease base-oil viscosity at 40 C (method = grease; 0 = the oil's nu40)"),

    REAL("mounting", "shaft_bore_mm", "mm", shaft_bore, 1e-3, 0, CC, 0, 2000,
         "hollow-shaft bore d_s (0 = derive: 25/40 x bore, the seed's 25 mm for 7008C)"),
    REALP("mounting", "h_fit_outer_W_m2K", "W/(m^2 K)", h_fit_outer, 1.0, 5000, OC, 0, 1e7,
          "outer ring / housing contact conductance", 1000, 20000,
          "docs/physics.md section 8.1 ASSUMED calibration knob, 1e3-2e4"),
    REALP("mounting", "h_fit_inner_W_m2K", "W/(m^2 K)", h_fit_inner, 1.0, 20000, OC, 0, 1e7,
          "inner ring / shaft contact conductance", 1000, 50000,
          "docs/physics.md section 8.1 ASSUMED calibration knob, 1e3-5e4"),
    REALP("mounting", "h_face_W_m2K", "W/(m^2 K)", h_face, 1.0, 3000, OC, 0, 1e7,
          "clamped ring face conductance", 1000, 10000,
          "docs/physics.md section 8.1 ASSUMED calibration knob, 1e3-1e4"),
    REALP("mounting", "h_natural_W_m2K", "W/(m^2 K)", h_natural, 1.0, 10, OC, 0, 10000,
          "natural convection on the housing exterior", 5, 50,
          "docs/physics.md section 10 ASSUMED 10 (natural 5-25, fan-assisted 50)"),
    ENUM("mounting", "preload", preload, k_preload, ACBB_PRELOAD_FORCE,
         "force: axial load applied (dx free); displacement: dx fixed by preload_N"),
    REAL("mounting", "preload_N", "N", preload_force, 1.0, 300, CC, 0, 1e6,
         "preload force (sets dx at 20 C, 0 rpm when preload = displacement)"),
    ENUM("mounting", "tilt", tilt, k_tilt, ACBB_TILT_AUTO,
         "inner-ring tilt: auto and free (solved whenever radial load or moment act, 0 N m "
         "included), or held (0 whatever the loads: the ring kept square to the shaft)"),

    /* [set] (MODEL.md 14): a spindle set; single = today's one bearing */
    ENUM("set", "arrangement", set_arrangement, acbb_set_arrangement_names, ACBB_SET_SINGLE,
         "bearings on the shaft: single, DB (back-to-back), DF (face-to-face), DT (tandem), "
         "DBT (tandem pair + one, back-to-back), QBC (two tandem pairs, back-to-back)"),
    INT("set", "n_bearings", set_n_bearings, 0, 0, 8,
        "bearings in the set (0 = the arrangement's count; DT: 2-4 in tandem)"),
    REAL("set", "spacing_mm", "mm", set_spacing, 1e-3, 0, CC, 0, 10000,
         "centre distance of neighbouring bearings (0 = adjacent: one width; spacers are the rest)"),
    REAL("set", "load_offset_mm", "mm", set_load_offset, 1e-3, 0, CC, -10000, 10000,
         "where the external loads act: nose position minus the set's centre, along the shaft"),
    REAL("set", "spacer_expansion_ppm_K", "ppm/K", set_spacer_chi, 1e-6, 0, CC, 0, 100,
         "spacer material: its expansion coefficient (0 = inner spacer as the shaft, outer as "
         "the housing)"),
    REAL("set", "inner_spacer_mm", "mm", set_inner_spacer, 1e-3, 0, CC, 0, 10000,
         "inner (shaft side) spacer length between neighbours (0 = the gap: spacing - width, "
         "matched spacers); its growth separates the inner rings"),
    REAL("set", "outer_spacer_mm", "mm", set_outer_spacer, 1e-3, 0, CC, 0, 10000,
         "outer (housing side) spacer length between neighbours (0 = the gap: spacing - width, "
         "matched spacers); its growth separates the outer rings"),

    /* [surroundings] (MODEL.md 8.1, 13): 0 = derive from the bearing by
     * scaling the seed's 7008C rig (acbb_scene_surroundings in scene.h) */
    REAL("surroundings", "housing_outer_diameter_mm", "mm", housing_od, 1e-3, 0, CC, 0, 10000,
         "housing outer diameter (0 = derive: 120/68 x bearing OD; material: materials.housing_*)"),
    REAL("surroundings", "housing_length_mm", "mm", housing_length, 1e-3, 0, CC, 0, 10000,
         "housing length, centred on the bearing (0 = derive: 3 x width)"),
    ENUM("surroundings", "housing_exterior", housing_bc, k_bc, ACBB_BC_CONVECTIVE,
         "housing exterior: convective (mounting.h_natural_W_m2K to ambient) or fixed at ambient"),
    REAL("surroundings", "shaft_length_mm", "mm", shaft_length, 1e-3, 0, CC, 0, 10000,
         "shaft segment carried by the network (0 = derive: 3 x width)"),
    FACE_BC("shaft_bore", bore_bc, "shaft bore", 500, 100, 2000,
            "ASSUMED: forced air / oil mist in a bore, 1e2-2e3 (docs/physics.md section 13)"),
    REAL("surroundings", "cap_outer_diameter_mm", "mm", cap_od, 1e-3, 0, CC, 0, 10000,
         "end cap outer diameter (0 = derive: the housing outer diameter)"),
    REAL("surroundings", "cap_thickness_mm", "mm", cap_thickness, 1e-3, 0, CC, 0, 1000,
         "end cap thickness (0 = derive: 2/3 x width)"),
    FACE_BC("cap", cap_bc, "end cap outer face", 10, 5, 50,
            "ASSUMED: as the housing exterior, natural 5 to fan-assisted 50"),

    REAL("operating", "inner_speed_rpm", "rpm", inner_speed, ACBB_RPM, 15000, CC, 0, 100000,
         "inner ring speed"),
    REAL("operating", "axial_load_N", "N", axial_load, 1.0, 1000, CC, 0, 1e6,
         "axial load F_x on the inner ring"),
    REAL("operating", "radial_load_N", "N", radial_load, 1.0, 0, CC, 0, 1e6,
         "radial load F_z"),
    REAL("operating", "moment_load_Nm", "N m", moment_load, 1.0, 0, CC, -1e5, 1e5,
         "tilting moment M_y"),
    REAL("operating", "ambient_C", "C", ambient_C, 1.0, 26, CC, -50, 300,
         "ambient = assembly reference temperature"),

    BOOL("effects", "heating", heating, 1,
         "power losses heat the bearing (off: isothermal at ambient_C, mechanics only)"),
    BOOL("effects", "thermal_expansion", thermal_expansion, 1,
         "thermal expansion of the parts (TE; off = WTE)"),
    BOOL("effects", "centrifugal", centrifugal, 1, "ball centrifugal force"),
    BOOL("effects", "gyroscopic", gyroscopic, 1, "gyroscopic moment on the balls"),
    BOOL("effects", "ring_centrifugal", ring_centrifugal, 1,
         "centrifugal growth of the inner ring"),
    BOOL("effects", "ehl_film", ehl_film, 1, "EHL film (off: boundary friction only)"),
    BOOL("effects", "loss_shear", loss_shear, 1, "lubricant shear loss P_L"),
    BOOL("effects", "loss_slip", loss_slip, 1, "sliding loss P_t"),
    BOOL("effects", "loss_spin", loss_spin, 1, "spin loss P_s"),
    BOOL("effects", "loss_rolling", loss_rolling, 1, "rolling (hysteresis) loss P_r"),
    BOOL("effects", "loss_drag", loss_drag, 1, "drag loss P_v"),
    BOOL("effects", "loss_cage", loss_cage, 0,
         "cage-land shear loss P_c (Petroff, outer-land guided cage)"),
    BOOL("effects", "loss_ehl_rolling", loss_ehl_rolling, 0,
         "EHL rolling resistance P_e (docs/physics.md section 16; the extended loss set)"),
    BOOL("effects", "loss_churning", loss_churning, 0,
         "oil churning (bath) / jet momentum loss P_ch (docs/physics.md section 16; the extended "
         "loss set)"),

    ENUM("fidelity", "model", model, k_model, ACBB_MODEL_QUASI_DYNAMIC,
         "ball mechanics: static Hertz ... dynamic"),
    INT("fidelity", "contact_grid", contact_grid, 6, 2, 64,
        "Gauss points per axis of the contact ellipse"),
    ENUM("fidelity", "hertz", hertz, k_hertz, ACBB_HERTZ_BH77,
         "ellipticity: exact integrals or curve fits (docs/physics.md section 2)"),
    ENUM("fidelity", "geometry", geometry, k_clean_seed, ACBB_GEOM_CLEAN,
         "clean geometry or the seed's literal eqs 12-13"),
    ENUM("fidelity", "race_control", race_control, k_race, ACBB_RACE_OUTER,
         "race control hypothesis (docs/physics.md section 4)"),
    ENUM("fidelity", "loss_form", loss_form, k_clean_seed, ACBB_LOSS_CLEAN,
         "loss equations: clean or the seed's literal form (docs/physics.md section 6)"),
    ENUM("fidelity", "hysteresis_axis", hyst_axis, k_hyst, ACBB_HYST_MAJOR,
         "ellipse axis used in the rolling loss P_r (rolling_hysteresis = seed)"),
    ENUM("fidelity", "rolling_hysteresis", roll_hyst, k_roll_hyst, ACBB_ROLL_HYST_SEED,
         "rolling hysteresis force in P_r: seed (Eq. 18, 4 eps Q a/(3 pi D)) or johnson "
         "(sphere, 3/16 eps Q b/R_x, b along rolling; Johnson 1985 ch. 9)"),
    REAL("fidelity", "mech_tol", "", mech_tol, 1.0, 1e-8, CC, 1e-14, 1e-3,
         "relative force residual of the mechanics solve"),
    REAL("fidelity", "steady_tol_K_s", "K/s", steady_tol, 1.0, 1e-4, OC, 0, 1,
         "steady state when every |dT/dt| is below this"),
    ENUM("fidelity", "network", network, k_network, ACBB_NET_46,
         "thermal network: 46 nodes or the 7-node teaching one"),
    ENUM("fidelity", "thermal_mode", thermal_mode, k_thermal_mode, ACBB_THERMAL_TRANSIENT,
         "transient (time steps) or steady (direct) thermal solve"),
    REAL("fidelity", "time_step_s", "s", time_step, 1.0, 5, OC, 0, 3600,
         "initial thermal time step (adaptive)"),
    ENUM("fidelity", "preset", fidelity_preset, k_fid_preset, ACBB_FIDELITY_CUSTOM,
         "named measured settings; overrides the knobs above unless custom"),
    REAL("fidelity", "target_error_pct", "%", target_error, 0.01, 0, CC, 0, 100,
         "cheapest stored settings within this error (0 = off; wins over preset)"),
    REAL("fidelity", "max_wall_s", "s", max_wall_s, 1.0, 0, CC, 0, 1e7,
         "wall-clock bound of a run, set-up included (0 = none): ends wall_limit, last good state kept"),

    REAL("thermal", "max_time_s", "s", max_time, 1.0, 36000, OC, 0, 1e8,
         "simulated time limit"),
    INT("thermal", "max_steps", max_steps, 20000, 1, 10000000, "coupled step limit"),
    REAL("thermal", "temp_limit_C", "C", temp_limit_C, 1.0, 150, CC, -50, 300,
         "runaway when any node is hotter than this"),
    REALP("thermal", "contact_multiplier", "", contact_multiplier, 1.0, 1, OC, 0, 1000,
          "multiplier c_mv on the race-side spot resistances", 0.5, 2,
          "docs/physics.md section 8.1 ASSUMED c_mv = 1, no range quoted: x/2 to x2"),
    ENUM("thermal", "contact_model", contact_model, k_contact, ACBB_CONTACT_STATIONARY,
         "contact spot resistances: stationary spots (seed) or moving heat source "
         "(each surface passes the contact; docs/contact_heat.md)"),
    REALP("thermal", "heat_partition", "", heat_partition, 1.0, 0.5, CC, 0, 1,
          "share phi_p of contact heat to the rings (7-node network)", 0.2, 0.8,
          "docs/physics.md section 8.3 phi_p = 0.5 (7-node network only), 0.2-0.8"),

    /* [life] (MODEL.md 15) */
    REAL("life", "reliability_pct", "%", life_reliability, 1.0, 90, CC, 90, 99.95,
         "reliability of the modified life L_nm (ISO 281 Table 12: a_1)"),
    REAL("life", "contamination_ec", "", life_ec, 1.0, 0.5, CC, 0, 1,
         "contamination factor e_c; 0.5 = normal cleanliness, D_pw < 100 mm (ISO 281 Table 13)"),
    REAL("life", "fatigue_limit_N", "N", life_Cu, 1.0, 0, CC, 0, 1e8,
         "fatigue load limit C_u (0 = C0/22, ISO 281 Annex B)"),
    REAL("life", "inner_shoulder_mm", "mm", life_shoulder_inner, 1e-3, 0, CC, 0, 100,
         "inner-ring shoulder height over the groove bottom (0 = from the inner land)"),
    REAL("life", "outer_shoulder_mm", "mm", life_shoulder_outer, 1e-3, 0, CC, 0, 100,
         "outer-ring shoulder height over the groove bottom (0 = from the outer land)"),
    BOOL("life", "internals_estimated", life_estimated, 0,
         "ball set and grooves are estimates (acbb new): C and C0 are too"),

    /* [physics] (physics_profile.h): the defaults of the keys it names */
    ENUM("physics", "profile", profile, k_profile, ACBB_PROFILE_SEED,
         "physics the loss keys default to: seed (the paper's, as printed) or reference "
         "(best-founded: Johnson hysteresis, EHL rolling, churning, cage); a key set "
         "explicitly wins"),

#include "scene_schema_spindle.h"
};

const size_t acbb_sf_n = sizeof acbb_sf_table / sizeof acbb_sf_table[0];
_Static_assert(sizeof acbb_sf_table / sizeof acbb_sf_table[0] <= ACBB_SF_MAX, "raise ACBB_SF_MAX");

/* ---- raw access through the table (memcpy: no type punning) ---- */

double acbb_sf_get_real(const acbb_scene *s, const acbb_sfield *f)
{
    double v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

int acbb_sf_get_int(const acbb_scene *s, const acbb_sfield *f)
{
    int v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

static bool acbb_sf_get_bool(const acbb_scene *s, const acbb_sfield *f)
{
    bool v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

/* Store a value given in preset units (enum: index, bool: 0/1). */
void acbb_sf_put(acbb_scene *s, const acbb_sfield *f, double v)
{
    char *p = (char *)s + f->off;
    if (f->info.type == ACBB_FIELD_REAL) {
        double si = v * f->scale;
        memcpy(p, &si, sizeof si);
    } else if (f->info.type == ACBB_FIELD_BOOL) {
        bool b = v != 0.0;
        memcpy(p, &b, sizeof b);
    } else {
        int i = (int)v;
        memcpy(p, &i, sizeof i);
    }
}

size_t acbb_sf_n_choices(const acbb_sfield *f)
{
    size_t n = 0;
    while (f->info.choices[n]) n++;
    return n;
}

/* ---- number formatting ---- */

/* Cost of a candidate text: its length, exponent forms counted 2 longer so
 * that "36000" wins over "3.6e+04" but "1e-10" over "0.0000000001". */
static size_t text_cost(const char *t)
{
    return strlen(t) + (strchr(t, 'e') ? 2 : 0);
}

/* Shortest decimal text t with strtod(t) * scale == si exactly, so that
 * load(save(s)) == s. First collect the preset numbers p near si / scale
 * (a few ulps either side) with p * scale == si, then print each with
 * increasing precision. An SI value that is the image of no preset number
 * (possible when scale != 1, e.g. an rpm speed computed in rad/s) is written
 * as %.17g of si / scale and comes back within an ulp. */
#define ULP_WINDOW 4

static void format_real(double si, double scale, char *buf, size_t n)
{
    if (si == 0.0) {   /* the window would step over +0 from -0 */
        snprintf(buf, n, "0");
        return;
    }
    double exact[2 * ULP_WINDOW + 1], p = si / scale;
    int n_exact = 0;
    for (int k = 0; k < ULP_WINDOW; k++) p = nextafter(p, -INFINITY);
    for (int k = 0; k <= 2 * ULP_WINDOW; k++, p = nextafter(p, INFINITY))
        if (p * scale == si) exact[n_exact++] = p;

    char best[40] = "", t[40];
    for (int prec = 1; prec <= 17; prec++) {
        for (int c = 0; c < n_exact; c++) {
            acbb_snprintf_c(t, sizeof t, "%.*g", prec, exact[c]);
            bool same = acbb_strtod_c(t, NULL) * scale == si;
            if (same && (best[0] == '\0' || text_cost(t) < text_cost(best)))
                memcpy(best, t, sizeof t);
        }
    }
    if (best[0] == '\0') acbb_snprintf_c(best, sizeof best, "%.17g", si / scale);
    snprintf(buf, n, "%s", best);
}

static const char *unit_suffix(const acbb_sfield *f, char *buf, size_t n)
{
    snprintf(buf, n, "%s%s", f->info.unit[0] ? " " : "", f->info.unit);
    return buf;
}

/* Why v (preset units) is out of range; "" if it is inside. A value below
 * the range names the lower bound only; above it, the whole range. */
/* v against f's ends times `scale` (1: preset units; f->scale: SI): -1
 * below, 1 above, 0 inside. */
static int range_side(const acbb_sfield *f, double v, double scale)
{
    bool lo_open = f->ends == OC || f->ends == OO, hi_open = f->ends == CO || f->ends == OO;
    double lo = f->info.min * scale, hi = f->info.max * scale;
    if (lo_open ? v <= lo : v < lo) return -1;
    return (hi_open ? v >= hi : v > hi) ? 1 : 0;
}

int acbb_sf_out_of_range_si(const acbb_sfield *f, double v)
{
    return range_side(f, v, f->scale) != 0;
}

void acbb_sf_range_reason(const acbb_sfield *f, double v, char *buf, size_t n)
{
    const acbb_field_info *in = &f->info;
    bool lo_open = f->ends == OC || f->ends == OO, hi_open = f->ends == CO || f->ends == OO;
    int side = range_side(f, v, 1.0);
    bool below = side < 0, above = side > 0;
    if (!below && !above) { /* every field of every validation: no text to make */
        buf[0] = '\0';
        return;
    }
    char u[32];
    unit_suffix(f, u, sizeof u);
    if (below)
        snprintf(buf, n, "must be %s %.15g%s", lo_open ? ">" : ">=", in->min, u);
    else if (above && !lo_open && !hi_open)
        snprintf(buf, n, "must be between %.15g and %.15g%s", in->min, in->max, u);
    else if (above)
        snprintf(buf, n, "must be %s %.15g and %s %.15g%s", lo_open ? ">" : ">=", in->min,
                 hi_open ? "<" : "<=", in->max, u);
}

/* ---- schema introspection ---- */

size_t acbb_scene_field_count(void) { return acbb_sf_n; }

const acbb_field_info *acbb_scene_field(size_t i)
{
    return i < acbb_sf_n ? &acbb_sf_table[i].info : NULL;
}

void acbb_scene_field_format(const acbb_scene *s, size_t i, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (i >= acbb_sf_n) return;
    const acbb_sfield *f = &acbb_sf_table[i];
    switch (f->info.type) {
    case ACBB_FIELD_REAL:
        format_real(acbb_sf_get_real(s, f), f->scale, buf, n);
        break;
    case ACBB_FIELD_INT:
        snprintf(buf, n, "%d", acbb_sf_get_int(s, f));
        break;
    case ACBB_FIELD_BOOL:
        snprintf(buf, n, "%s", acbb_sf_get_bool(s, f) ? "on" : "off");
        break;
    case ACBB_FIELD_ENUM: {
        int v = acbb_sf_get_int(s, f);
        bool known = v >= 0 && (size_t)v < acbb_sf_n_choices(f);
        snprintf(buf, n, "%s", known ? f->info.choices[v] : "?");
        break;
    }
    }
}

/* Allowed values as text; numbers either as "0 < x <= 100 mm" or, with
 * `interval`, as "(0, 100] mm". */
static void describe_range(size_t i, bool interval, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (i >= acbb_sf_n) return;
    const acbb_sfield *f = &acbb_sf_table[i];
    char u[32];
    size_t used = 0;
    bool lo_open = f->info.min_open, hi_open = f->info.max_open;
    switch (f->info.type) {
    case ACBB_FIELD_REAL:
    case ACBB_FIELD_INT:
        if (interval)
            snprintf(buf, n, "%c%.15g, %.15g%c%s", lo_open ? '(' : '[', f->info.min, f->info.max,
                     hi_open ? ')' : ']', unit_suffix(f, u, sizeof u));
        else
            snprintf(buf, n, "%.15g %s x %s %.15g%s", f->info.min, lo_open ? "<" : "<=",
                     hi_open ? "<" : "<=", f->info.max, unit_suffix(f, u, sizeof u));
        break;
    case ACBB_FIELD_BOOL:
        snprintf(buf, n, "on | off");
        break;
    case ACBB_FIELD_ENUM:
        for (size_t c = 0; f->info.choices[c] && used < n; c++)
            used += (size_t)snprintf(buf + used, n - used, "%s%s", c ? " | " : "",
                                     f->info.choices[c]);
        break;
    }
}

void acbb_scene_field_range(size_t i, char *buf, size_t n)
{
    describe_range(i, false, buf, n);
}

void acbb_scene_field_interval(size_t i, char *buf, size_t n)
{
    describe_range(i, true, buf, n);
}

void acbb_scene_field_plausible(size_t i, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (i >= acbb_sf_n || !acbb_sf_table[i].info.plaus_src) return;
    const acbb_sfield *f = &acbb_sf_table[i];
    char u[32];
    if (f->info.type == ACBB_FIELD_ENUM)
        snprintf(buf, n, "%s | %s; %s", f->info.choices[(int)f->info.plaus_lo],
                 f->info.choices[(int)f->info.plaus_hi], f->info.plaus_src);
    else
        snprintf(buf, n, "[%.15g, %.15g]%s; %s", f->info.plaus_lo, f->info.plaus_hi,
                 unit_suffix(f, u, sizeof u), f->info.plaus_src);
}

const char *acbb_model_level_name(acbb_model_level m)
{
    return m >= ACBB_MODEL_STATIC && m <= ACBB_MODEL_DYNAMIC ? k_model[m] : "unknown";
}

/* ---- sections (the table lists each section's keys together) ---- */

static bool starts_section(size_t i)
{
    return i == 0 || strcmp(acbb_sf_table[i].info.section, acbb_sf_table[i - 1].info.section) != 0;
}

size_t acbb_sf_section_count(void)
{
    size_t k = 0;
    for (size_t i = 0; i < acbb_sf_n; i++) k += starts_section(i);
    return k;
}

const char *acbb_sf_section_name(size_t k)
{
    for (size_t i = 0; i < acbb_sf_n; i++)
        if (starts_section(i) && k-- == 0) return acbb_sf_table[i].info.section;
    return NULL;
}

/* One pass over the table (a preset's every key line asks: the pass over
 * each section name in turn cost 1.7 M instructions a load). */
int acbb_sf_section_index(const char *name)
{
    int k = -1;
    for (size_t i = 0; i < acbb_sf_n; i++) {
        if (!starts_section(i)) continue;
        if (++k >= ACBB_SF_SECTIONS_MAX) return -1;
        if (strcmp(acbb_sf_table[i].info.section, name) == 0) return k;
    }
    return -1;
}

void acbb_scene_default(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    for (size_t i = 0; i < acbb_sf_n; i++)
        acbb_sf_put(s, &acbb_sf_table[i], acbb_sf_table[i].def);
}

/* The schema's ball-count range must match what the engine holds. */
_Static_assert(ACBB_MAX_BALLS == 64, "bearing.n_balls range in the schema is 3..64");
