/* The seed study tests' scene: the 7008C preset, or bail out (TAP). */
#ifndef ACBB_TEST_STUDY_PRESET_H
#define ACBB_TEST_STUDY_PRESET_H

#include <stdio.h>
#include <stdlib.h>
#include "acbb/scene.h"

#define PRESET "presets/7008C.ini"

static acbb_scene preset(void)
{
    acbb_scene s;
    acbb_error err = { { 0 } };
    if (acbb_scene_load(PRESET, &s, &err) != ACBB_OK) {
        printf("Bail out! cannot load %s: %s\n", PRESET, err.msg);
        exit(1);
    }
    return s;
}

#endif
