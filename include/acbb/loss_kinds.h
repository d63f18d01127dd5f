/* acbb — the kinds of power loss a run reports (MODEL.md section 6): what a
 * client lists. The formulas and where each one's heat goes are engine
 * internals (src/physics/losses.h). */
#ifndef ACBB_LOSS_KINDS_H
#define ACBB_LOSS_KINDS_H

#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ACBB_LOSS_SHEAR,    /* P_L lubricant shear */
    ACBB_LOSS_SLIP,     /* P_t differential slipping (asperity) */
    ACBB_LOSS_SPIN,     /* P_s spinning */
    ACBB_LOSS_ROLLING,  /* P_r rolling (elastic hysteresis) */
    ACBB_LOSS_DRAG,     /* P_v oil-air drag */
    ACBB_LOSS_CAGE,     /* P_c cage-land shear (Petroff), MODEL.md 6 note iii */
    ACBB_LOSS_EHL_ROLLING, /* P_e EHL rolling resistance, MODEL.md 16 */
    ACBB_LOSS_CHURNING, /* P_ch oil-bath churning / oil-jet momentum, MODEL.md 16 */
    ACBB_LOSS_KINDS
} acbb_loss_kind;

/* Names of loss k (static strings): the JSON / CSV key ("shear"), the
 * symbol ("P_L"), the label ("lubricant shear"). */
const char *acbb_loss_name(acbb_loss_kind k);
const char *acbb_loss_symbol(acbb_loss_kind k);
const char *acbb_loss_label(acbb_loss_kind k);

/* Which set of losses a scene uses (MODEL.md 16): "seed" (the five of
 * [S], and the optional cage loss) or "extended" (EHL rolling resistance
 * or churning on as well). Static string. */
const char *acbb_loss_set(const acbb_scene *s);

/* Is loss k switched on in the scene ([effects] loss_*)? */
int acbb_loss_enabled(const acbb_scene *s, acbb_loss_kind k);

#ifdef __cplusplus
}
#endif

#endif
