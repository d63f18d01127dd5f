/* acbb — the first state's mechanics and Level-2 passes of a transient
 * taken from another run's (issue 30: `report --sensitivity`'s perturbed
 * transients, most of whose inputs are the thermal network's). A run that
 * took its set-up's mechanics from a kept set-up (sim.c, acbb_sim_setup)
 * starts its first state's mechanics (sim_eval.c `mechanics`) from the
 * same workspace and state as the run that kept it. The passes are then
 * a function of what they read besides: the expansions, the oil at the
 * two inlets and the cavity's mixture, the scene and the Level-2
 * workspace as made afresh (acbb_qd_new, acbb_qd_renew). Where all of
 * those are the same bits, so is their result: the state, the mechanics
 * workspace and the Level-2 workspace as the passes leave them, kept
 * here by the first run and taken by the others. */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "sim_struct.h"

/* The scene's fields that neither the mechanics solve (it reads none after
 * acbb_mech_new, whose copy acbb_mech_same compares) nor Level 2 reads:
 * the thermal network's; the contacts' hysteresis (losses.c's rolling
 * losses only, made after the passes); the expansion coefficients and
 * the oil's specific heat, which reach the passes only through the
 * expansions and the mixture compared below (the mixture's specific heat,
 * the network's, not compared). Every other byte of the scene is
 * compared, so a field missing here only costs the passes. */
static const struct {
    size_t off, len;
} not_read[] = {
#define FIELD(f) { offsetof(acbb_scene, f), sizeof(((acbb_scene *)0)->f) }
    FIELD(ball.chi), FIELD(ring.chi), FIELD(shaft.chi), FIELD(housing.chi), FIELD(cage.chi),
    FIELD(mix_k), FIELD(h_fit_outer), FIELD(h_fit_inner), FIELD(h_face), FIELD(h_natural),
    FIELD(bore_bc), FIELD(cap_bc), FIELD(contact_multiplier), FIELD(heat_partition),
    FIELD(hysteresis), FIELD(oil_cp),
#undef FIELD
};

struct acbb_sim_first {
    acbb_scene s;              /* the scene, its not_read fields zeroed */
    acbb_expansion exp;
    acbb_oil_state oi, oo;     /* the oil at the inner and outer inlets */
    acbb_mixture mix;          /* the cavity's oil-air mixture (mix_read) */
    acbb_mech *mech;           /* the mechanics workspace as the passes left it */
    acbb_qd *qd;               /* the Level-2 workspace as they left it (acbb_qd_save) */
    acbb_mech_state ms;        /* the state they reached */
};

static void masked(const acbb_scene *s, acbb_scene *out)
{
    memcpy(out, s, sizeof *out);
    for (size_t k = 0; k < sizeof not_read / sizeof not_read[0]; k++)
        memset((char *)out + not_read[k].off, 0, not_read[k].len);
}

/* The mixture as the passes read it (the drag: its density): all but
 * the specific heat, which only the network reads. */
static acbb_mixture mix_read(const acbb_mixture *mix)
{
    acbb_mixture m = *mix;
    m.cp = 0.0;
    return m;
}

void acbb_simx_first_free(acbb_sim_first *f)
{
    if (!f) return;
    acbb_mech_free(f->mech);
    free(f->qd);
    free(f);
}

/* 1 if the passes at these inputs are f's. */
static int same_inputs(const acbb_sim *sim, const acbb_sim_first *f, const acbb_oil_state *oi,
                       const acbb_oil_state *oo, const acbb_mixture *mix)
{
    acbb_mixture m = mix_read(mix);
    if (memcmp(&f->exp, &sim->exp, sizeof f->exp) != 0 || memcmp(&f->oi, oi, sizeof *oi) != 0
        || memcmp(&f->oo, oo, sizeof *oo) != 0 || memcmp(&f->mix, &m, sizeof m) != 0)
        return 0;
    acbb_scene s;
    masked(&sim->s, &s);
    return memcmp(&f->s, &s, sizeof s) == 0;
}

int acbb_simx_first_take(acbb_sim *sim, const acbb_oil_state *oi, const acbb_oil_state *oo,
                         const acbb_mixture *mix)
{
    const acbb_sim_first *f = sim->setup_from ? sim->setup_from->first : NULL;
    if (!f || !sim->qd || sim->dyn || !same_inputs(sim, f, oi, oo, mix)) return 0;
    acbb_mech_adopt(sim->mech, f->mech);
    acbb_qd_restore(sim->qd, f->qd);
    acbb_mech_state_copy(&sim->ms, &f->ms);
    return 1;
}

void acbb_simx_first_keep(acbb_sim *sim, const acbb_oil_state *oi, const acbb_oil_state *oo,
                          const acbb_mixture *mix)
{
    if (!sim->setup || sim->setup->first || !sim->qd || sim->dyn) return;
    acbb_sim_first *f = malloc(sizeof *f);
    if (!f) return;
    masked(&sim->s, &f->s);
    f->exp = sim->exp;
    f->oi = *oi;
    f->oo = *oo;
    f->mix = mix_read(mix);
    f->mech = acbb_mech_keep(sim->mech);
    f->qd = acbb_qd_save(sim->qd);
    acbb_mech_state_copy(&f->ms, &sim->ms);
    if (!f->mech || !f->qd) {
        acbb_simx_first_free(f);
        return;
    }
    sim->setup->first = f;
}
