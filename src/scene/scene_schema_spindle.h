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
    REAL("shaft", "end_film_W_m2K", "W/(m^2 K)", shaft_h_end, 1.0, 10, CC, 0, 10000,
         "film coefficient of the shaft's two end faces to the air (0 = adiabatic; 10: natural "
         "convection, gases 2-25, Incropera Table 1.1)"),

    /* [housing]: material materials.housing_* */
    INT("housing", "segments", housing_segments, 0, 0, ACBB_SPINDLE_MAX_SEG,
        "segments of the spindle housing from its front end (a spindle needs >= 1)"),
    SPINDLE_SEGS("housing", housing_seg, "the bore the outer rings sit in"),
    REAL("housing", "x0_mm", "mm", housing_x0, 1e-3, 0, CC, 0, 10000,
         "where the housing's first segment starts, from the nose"),
    REAL("housing", "outer_film_W_m2K", "W/(m^2 K)", housing_h_outer, 1.0, 10, CC, 0, 10000,
         "film coefficient of the housing's outer surface to the air (10: natural convection, "
         "gases 2-25, Incropera Table 1.1)"),

    /* [motor]: a built-in motor's losses (0 = belt-driven, no motor) */
    REAL("motor", "rotor_loss_W", "W", motor_rotor_loss, 1.0, 0, CC, 0, 1e6,
         "rotor loss, spread over the shaft cells between x0_mm and x1_mm"),
    REAL("motor", "stator_loss_W", "W", motor_stator_loss, 1.0, 0, CC, 0, 1e6,
         "stator loss, spread over the housing cells between x0_mm and x1_mm"),
    REAL("motor", "x0_mm", "mm", motor_x0, 1e-3, 0, CC, 0, 10000,
         "front end of rotor and stator, from the nose"),
    REAL("motor", "x1_mm", "mm", motor_x1, 1e-3, 0, CC, 0, 10000,
         "rear end of rotor and stator, from the nose (x1_mm = x0_mm: no motor)"),
    REAL("motor", "gap_conductance_W_K", "W/K", motor_gap_G, 1.0, 0, CC, 0, 1e6,
         "rotor-stator conductance across the air gap, whole motor (0 = none)"),

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
    REAL("spindle", "rear_spring_N", "N", spindle_rear_spring, 1.0, 300, CC, 0, 1e6,
         "rear_support = spring: the springs' axial force on the rear set, reacted by the front"),
    REAL("spindle", "rear_friction_N", "N", spindle_rear_friction, 1.0, 0, CC, 0, 1e6,
         "rear_support = floating: sliding friction of the sleeve (0 = frictionless)"),
    REAL("spindle", "coolant_flow_l_min", "L/min", coolant_flow, 1e-3 / 60.0, 0, CC, 0, 1000,
         "cooling jacket flow (0 = no coolant)"),
    REAL("spindle", "coolant_inlet_dT_K", "K", coolant_inlet_dT, 1.0, 0, CC, -100, 200,
         "coolant inlet temperature minus operating.ambient_C"),
    REAL("spindle", "coolant_density_kg_m3", "kg/m^3", coolant_rho, 1.0, 1000, OC, 0, 30000,
         "coolant density (water: 997 at 300 K, Incropera Table A.6)"),
    REAL("spindle", "coolant_cp_J_kgK", "J/(kg K)", coolant_cp, 1.0, 4180, OC, 0, 100000,
         "coolant specific heat (water: 4179 at 300 K, Incropera Table A.6)"),
    REAL("spindle", "jacket_x0_mm", "mm", jacket_x0, 1e-3, 0, CC, 0, 10000,
         "front end of the cooling jacket on the housing, from the nose"),
    REAL("spindle", "jacket_x1_mm", "mm", jacket_x1, 1e-3, 0, CC, 0, 10000,
         "rear end of the cooling jacket (x1_mm = x0_mm: no jacket)"),
    REAL("spindle", "jacket_hA_W_K", "W/K", jacket_hA, 1.0, 0, CC, 0, 1e7,
         "jacket wall conductance, whole jacket: film h times wetted area (> 0 with coolant)"),
    INT("spindle", "coolant_cells", coolant_cells, 8, 1, 64,
        "well-mixed coolant cells along the jacket (the coolant warms cell by cell)"),

#undef SPINDLE_SEGS
#undef SPINDLE_SEG
