/* Test helper (header-only): a node of a parsed JSON document by a path
 * as a user types it and `acbb metrics` lists it: names split at '.', a
 * name "x[K]" is item K of array x ("balls[3].losses_W.spin",
 * "spindle.sets[0].preload_N"). NULL when the path leads nowhere. */
#ifndef ACBB_TEST_JSON_PATH_H
#define ACBB_TEST_JSON_PATH_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>

static inline const cJSON *json_path(const cJSON *root, const char *path)
{
    char tok[64];
    const cJSON *node = root;
    while (node && *path) {
        size_t len = strcspn(path, ".");
        snprintf(tok, sizeof tok, "%.*s", (int)len, path);
        char *br = strchr(tok, '[');
        if (br) *br = '\0';
        node = cJSON_GetObjectItemCaseSensitive(node, tok);
        if (br) node = cJSON_GetArrayItem(node, atoi(br + 1));
        path += len + (path[len] == '.');
    }
    return node;
}

#endif
