/* acbb CLI — `acbb report`'s section on the contact heat models: which
 * branch the runaway case reaches under each thermal.contact_model and
 * race-side thermal.contact_multiplier (include/acbb/tools/contact_study.h),
 * as text (80 columns), Markdown and the JSON member "contact_heat". */
#ifndef ACBB_CLI_REPORT_CONTACT_H
#define ACBB_CLI_REPORT_CONTACT_H

#include <stdio.h>
#include "acbb/tools/contact_study.h"
#include "acbb/tools/json.h"

void acbb_report_contact_text(FILE *f, const acbb_contact_study *cs);
void acbb_report_contact_md(FILE *f, const acbb_contact_study *cs);
void acbb_report_contact_json(acbb_json *j, const acbb_contact_study *cs);

#endif
