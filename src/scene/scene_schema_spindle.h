/* acbb — the spindle's rows of the schema table (issue 31; docs/spindle.md
 * "Scene"): [shaft], [housing], [motor], [spindle].
 *
 * Not a header of its own: scene_schema.c includes it inside the
 * initializer of acbb_sf_table, after the other rows, so that the one table
 * keeps describing every key (scene_internal.h) while its spindle part
 * stays in a file of its own. It uses scene_schema.c's row macros (REAL,
 * INT, ENUM) and its choice lists.
 *
 * shaft.segments = 0 (the default) is no spindle: every other key here is
 * then unused (acbb_scene_inactive_effects names a changed one) and every
 * scene without these sections runs as before. */

/* Three keys per segment i (1-based) of the shaft or the housing, in mm;
 * 0 = not given (a segment up to `segments` must be given: scene_rules). */
#define SPINDLE_SEG(sec, i, member, bore_what) \
    REAL(sec, "seg" #i "_length_mm", "mm", member[i - 1].length, 1e-3, 0, CC, 0, 10000, \
         "length of " sec " segment " #i " (segments run from the nose to the rear)"), \
    REAL(sec, "seg" #i "_od_mm", "mm", member[i - 1].od, 1e-3, 0, CC, 0, 2000, \
         "outer diameter of " sec " segment " #i), \
    REAL(sec, "seg" #i "_bore_mm", "mm", member[i - 1].bore, 1e-3, 0, CC, 0, 2000, \
         "bore of " sec " segment " #i " (" bore_what "; < its od)")
#define SPINDLE_SEGS(sec, member, bore_what) \
    SPINDLE_SEG(sec, 1, member, bore_what), SPINDLE_SEG(sec, 2, member, bore_what), \
    SPINDLE_SEG(sec, 3, member, bore_what), SPINDLE_SEG(sec, 4, member, bore_what), \
    SPINDLE_SEG(sec, 5, member, bore_what), SPINDLE_SEG(sec, 6, member, bore_what), \
    SPINDLE_SEG(sec, 7, member, bore_what), SPINDLE_SEG(sec, 8, member, bore_what)

    /* [shaft]: x = 0 at the nose, growing towards the rear; material:
     * materials.shaft_* */
    INT("shaft", "segments", shaft_segments, 0, 0, ACBB_SPINDLE_MAX_SEG,
        "segments of the spindle shaft from the nose (0 = no spindle: a bearing or a set as "
        "before; >= 1: [bearing], [set] and [mounting] are the front set)"),
    SPINDLE_SEGS("shaft", shaft_seg, "0 = solid"),
    INT("shaft", "n_div", shaft_n_div, 4, 1, 20,
        "beam elements and thermal cells per segment of shaft and housing"),
    /* Plausible: free convection of gases 2-25 (Incropera Table 1.1); a
     * rotating end face sees more (ASSUMED up to 50, as
     * mounting.h_natural_W_m2K's fan-assisted end). */
    REALP("shaft", "end_film_W_m2K", "W/(m^2 K)", shaft_h_end, 1.0, 10, CC, 0, 10000,
          "film coefficient of the shaft's two end faces to the air (0 = adiabatic; 10: natural "
          "convection, gases 2-25, Incropera Table 1.1)", 5, 50,
          "ASSUMED: free convection 2-25 (Incropera Table 1.1), a rotating face more"),

    /* [housing]: material materials.housing_* */
    INT("housing", "segments", housing_segments, 0, 0, ACBB_SPINDLE_MAX_SEG,
        "segments of the spindle housing from its front end (a spindle needs >= 1)"),
    SPINDLE_SEGS("housing", housing_seg, "the bore the outer rings sit in"),
    REAL("housing", "x0_mm", "mm", housing_x0, 1e-3, 0, CC, 0, 10000,
         "where the housing's first segment starts, from the nose"),
    REALP("housing", "outer_film_W_m2K", "W/(m^2 K)", housing_h_outer, 1.0, 10, CC, 0, 10000,
          "film coefficient of the housing's outer surface to the air (10: natural convection, "
          "gases 2-25, Incropera Table 1.1)", 5, 25,
          "free convection of gases 2-25, Incropera Table 1.1"),

    /* [motor]: a built-in motor's losses (0 = belt-driven, no motor) */
    /* Plausible (the motor spindle preset's 150 and 300 W +-1/3): a motor's
     * losses at one operating point are not known better without the
     * maker's efficiency map, and the rotor:stator split (1:2, the split
     * often quoted after Bossmanns and Tu 1999) not at all; ASSUMED. */
    REALP("motor", "rotor_loss_W", "W", motor_rotor_loss, 1.0, 0, CC, 0, 1e6,
          "rotor loss, spread over the shaft cells between x0_mm and x1_mm", 100, 200,
          "ASSUMED: the motor preset's 150 W +-1/3 (no efficiency map, split uncertain)"),
    REALP("motor", "stator_loss_W", "W", motor_stator_loss, 1.0, 0, CC, 0, 1e6,
          "stator loss, spread over the housing cells between x0_mm and x1_mm", 200, 400,
          "ASSUMED: the motor preset's 300 W +-1/3 (no efficiency map, split uncertain)"),
    REAL("motor", "x0_mm", "mm", motor_x0, 1e-3, 0, CC, 0, 10000,
         "front end of rotor and stator, from the nose"),
    REAL("motor", "x1_mm", "mm", motor_x1, 1e-3, 0, CC, 0, 10000,
         "rear end of rotor and stator, from the nose (x1_mm = x0_mm: no motor)"),
    /* Plausible: still air's conduction across the gap (the motor preset's
     * 1 W/K) is the lower bound; Taylor vortices in the rotating gap raise
     * the Nusselt number above conduction's (Fenot et al., "A review of
     * heat transfer between concentric rotating cylinders", Int. J. Therm.
     * Sci. 50 (2011) 1138); ASSUMED up to 3 times at these speeds. */
    REALP("motor", "gap_conductance_W_K", "W/K", motor_gap_G, 1.0, 0, CC, 0, 1e6,
          "rotor-stator conductance across the air gap, whole motor (0 = none)", 1, 3,
          "ASSUMED: conduction 1 W/K up to 3x (Taylor vortices; Fenot et al. 2011 review)"),

    /* [spindle]: the sets on the shaft, the rear support, the coolant */
    REAL("spindle", "front_x_mm", "mm", spindle_front_x, 1e-3, 0, CC, 0, 10000,
         "centre of the front set ([bearing], [set], [mounting]), from the nose"),
    REAL("spindle", "rear_x_mm", "mm", spindle_rear_x, 1e-3, 0, CC, 0, 10000,
         "centre of the rear set (the same bearing as the front), from the nose"),
    ENUM("spindle", "rear_support", spindle_rear_support, k_rear_support, ACBB_REAR_SPRING,
         "rear set held axially: fixed (located like the front), spring (sleeve pushed by "
         "rear_spring_N) or floating (sleeve sliding with rear_friction_N)"),
    ENUM("spindle", "rear_arrangement", spindle_rear_arrangement, acbb_set_arrangement_names,
         ACBB_SET_SINGLE, "bearings of the rear set: single, DB, DF, DT, DBT or QBC (as "
         "set.arrangement)"),
    REAL("spindle", "rear_spacing_mm", "mm", spindle_rear_spacing, 1e-3, 0, CC, 0, 10000,
         "centre distance of the rear set's neighbouring bearings (0 = adjacent: one width)"),
    REAL("spindle", "rear_preload_N", "N", spindle_rear_preload, 1.0, 0, CC, 0, 1e6,
         "rigid (spacer) preload of an opposed rear set at assembly"),
    /* Plausible ranges of the rear support and the coolant, around the
     * presets' values (ASSUMED, each with its reason): a spring pack's
     * force at its fitted length +-10 % (free length and rate
     * tolerances; the motor preset's 250 N); a sleeve's sliding friction
     * (fit, lubrication, O-ring squeeze) to a factor of 2 (the belt
     * preset's 40 N); a chiller's delivered flow +-25 % of its nominal 4
     * L/min (its pump curve against the circuit's pressure drop) and its
     * inlet held at the ambient +-1 K. */
    REALP("spindle", "rear_spring_N", "N", spindle_rear_spring, 1.0, 300, CC, 0, 1e6,
          "rear_support = spring: the springs' axial force on the rear set, reacted by the front",
          225, 275, "ASSUMED: the motor preset's 250 N +-10 % (spring force tolerance)"),
    REALP("spindle", "rear_friction_N", "N", spindle_rear_friction, 1.0, 0, CC, 0, 1e6,
          "rear_support = floating: sliding friction of the sleeve (0 = frictionless)", 20, 80,
          "ASSUMED: the belt preset's 40 N to a factor of 2 (fit, lubrication, O-rings)"),
    REALP("spindle", "coolant_flow_l_min", "L/min", coolant_flow, 1e-3 / 60.0, 0, CC, 0, 1000,
          "cooling jacket flow (0 = no coolant)", 3, 5,
          "ASSUMED: the motor preset's 4 L/min +-25 % (pump curve against the pressure drop)"),
    REALP("spindle", "coolant_inlet_dT_K", "K", coolant_inlet_dT, 1.0, 0, CC, -100, 200,
          "coolant inlet temperature minus operating.ambient_C", -1, 1,
          "ASSUMED: a chiller holding the inlet at the ambient +-1 K"),
    REAL("spindle", "coolant_density_kg_m3", "kg/m^3", coolant_rho, 1.0, 1000, OC, 0, 30000,
         "coolant density (water: 997 at 300 K, Incropera Table A.6)"),
    REAL("spindle", "coolant_cp_J_kgK", "J/(kg K)", coolant_cp, 1.0, 4180, OC, 0, 100000,
         "coolant specific heat (water: 4179 at 300 K, Incropera Table A.6)"),
    REAL("spindle", "jacket_x0_mm", "mm", jacket_x0, 1e-3, 0, CC, 0, 10000,
         "front end of the cooling jacket on the housing, from the nose"),
    REAL("spindle", "jacket_x1_mm", "mm", jacket_x1, 1e-3, 0, CC, 0, 10000,
         "rear end of the cooling jacket (x1_mm = x0_mm: no jacket)"),
    /* Plausible: the motor preset's 150 W/K is Dittus-Boelter's film
     * (Incropera eq. 8.60) times the wetted area; Incropera gives that
     * correlation's error as up to 25 %. */
    REALP("spindle", "jacket_hA_W_K", "W/K", jacket_hA, 1.0, 0, CC, 0, 1e7,
          "jacket wall conductance, whole jacket: film h times wetted area (> 0 with coolant)",
          112.5, 187.5, "the motor preset's 150 W/K +-25 %: Dittus-Boelter's error (Incropera 8.5)"),
    INT("spindle", "coolant_cells", coolant_cells, 8, 1, 64,
        "well-mixed coolant cells along the jacket (the coolant warms cell by cell)"),

#undef SPINDLE_SEGS
#undef SPINDLE_SEG
