#!/bin/sh
# Builds de_DE.UTF-8 (a decimal-comma locale) with localedef into a scratch
# LOCPATH, then runs test_locale ($1) under it; its TAP is this test's.
# Without localedef or Debian's `locales` sources the C test skips.
set -u
TMP=$(mktemp -d "${TMPDIR:-/tmp}/acbb-locale.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT INT TERM
mkdir -p "$TMP/loc"
localedef -i de_DE -f UTF-8 "$TMP/loc/de_DE.UTF-8" >/dev/null 2>&1 || true
LOCPATH=$TMP/loc "$1" "$TMP"
