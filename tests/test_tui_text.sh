#!/bin/sh
# Issue 29 item 7 (TAP, tmux, 80x24): nothing the user must read is cut at
# 80 columns. The quit question with a long preset name keeps its
# answers; the life line shows a_ISO (why Lnm is 50 x L10r) and marks
# lives at the reported cap with ">"; the Run screen's contact angles are
# alpha_i/alpha_o (a_i is the Balls screen's semi-axis); the help has a
# glossary of the short names; the Edit screen's columns fit every name.
# Usage: test_tui_text.sh PATH/TO/acbb   (cwd = repo root)
set -u
. "$(dirname "$0")/test_tui_lib.sh"

long=a-rather-long-preset-name-for-the-quit-prompt.ini
cp "$ROOT/presets/7008C.ini" "$TMP/$long"
TUI_ARGS="--pace 0" start "env NO_COLOR=1" tx "$long"
wait_for "Idle at ambient"
keys r
wait_for "100% done"
screen | grep '^Life' | grep -q "Lnm 2.37e+04 h *s0 .* a_ISO 19.8" &&
    [ "$(screen | grep '^Life' | awk '{ print length }')" -le 80 ]
ok $? "the life line at 80 columns shows a_ISO 19.8 (Lnm = a_ISO x L10r, C_u on the ISO 76 stress basis)"
screen | grep -q "alpha_i 19\.[0-9]*" && ! screen | grep -qw "a_i [0-9]*"
ok $? "the Run screen names the contact angles alpha_i, alpha_o"
keys '?' /
typekeys() { $T send-keys -t "$S" -l "$1"; }
typekeys "Glossary"
keys Enter
wait_for "contact ellipse semi-axes" && wait_for "contact angle at the"
ok $? "the help has a glossary: a_i is a semi-axis, alpha_i an angle"
keys Escape Escape 5
wait_for "Enter edit"
goto_field surroundings.housing_exterior
wait_for "surroundings.housing_exterior: "
screen | grep -q "^ surroundings housing_exterior           convective     fixed | derived" &&
    screen | tr -d '\n' | grep -q "allowed: fixed | *derived | *convective"
ok $? "Edit: the widest section and key stay in their columns; the info rows give the whole list of choices"
goto_field operating.axial_load_N
keys Enter C-u 900 Enter
wait_for "[modified]"
keys q
wait_for "Quit anyway?" && wait_for "n = stay"
ok $? "the quit question with a long preset name keeps its answers at 80 columns"
keys n
wait_for "not quitting"
keys o p
wait_for "open preset: "
keys "$ROOT/presets/hertz-contact.ini" Enter
wait_for "Discard them and open" && wait_for "y/n"
keys y
wait_for "opened $ROOT/presets/hertz-contact.ini" && wait_for "not started"
keys 1 r
wait_for "100% done" && wait_for "Life: "
screen | grep '^Life' | grep -q "L10r >1e+09 h *Lnm >1e+09 h"
ok $? "a life at the reported cap reads >1e+09 h"
keys q
wait_file "$TMP/tx"
echo "1..$n"
[ $failed -eq 0 ]
