# Test machinery: not part of any assignment. Sourced by course/mutants/grade.sh and
# course/platform/grade_local.sh.
# What the grader must say about a catalogued bug, kept in the bug's patch header (issue 31: every
# message met on the way to a fix names the cause), one line each:
#   Says: CASE: TEXT      results.json's verdict of image case CASE ("unit" for the part's unit
#                         tests), the text the report shows, contains TEXT;
#   Prints: TEXT          the grader's terminal output contains TEXT (the hints it prints);
#   Never says: TEXT      no verdict of the part contains TEXT (a sentence that would point the
#                         student the wrong way).
# And for every bug, whatever its patch says: no failed test's message is cmocka's bare comparison
# ("- `test_x`: 0 != 0xa"): each test says in its own words what was wrong.
# mutant_says PATCH PART RESULTS_JSON TERMINAL_LOG prints one "ok" or "FAIL" line per claim and
# returns non-zero when any claim fails. Needs jq.

mutant_says() {
    _patch=$1 _part=$2 _json=$3 _log=$4 _bad=0
    _claims=$(sed -n '/^--- /q; /^\(Says\|Prints\|Never says\): /p' "$_patch")
    _tmp=$(mktemp) || return 2
    jq -r --arg p "Part $_part: " '.tests[] | select(.name | startswith($p)) | .output' "$_json" >"$_tmp" 2>/dev/null
    if grep -qE '^- `[A-Za-z0-9_]+`: (0x)?[0-9a-f]+ != (0x)?[0-9a-f]+$' "$_tmp"; then
        echo "  FAIL  $(basename "$_patch" .patch): a failed test's message is cmocka's bare comparison:"
        grep -E '^- `[A-Za-z0-9_]+`: (0x)?[0-9a-f]+ != (0x)?[0-9a-f]+$' "$_tmp" | sed 's/^/        /'
        _bad=1
    fi
    [ -n "$_claims" ] || { rm -f "$_tmp"; return $_bad; }
    while IFS= read -r _claim; do
        case $_claim in
            "Says: "*)
                _rest=${_claim#Says: } _case=${_claim#Says: } _case=${_case%%: *} _text=${_rest#*: }
                if [ "$_case" = unit ]; then _name="Part $_part: unit tests"; else _name="Part $_part: image $_case"; fi
                jq -r --arg n "$_name" '.tests[] | select(.name == $n or .name == $n + " (hidden)") | .output' "$_json" >"$_tmp" 2>/dev/null
                grep -qF -- "$_text" "$_tmp" ;;
            "Prints: "*)
                _text=${_claim#Prints: }
                grep -qF -- "$_text" "$_log" ;;
            "Never says: "*)
                _text=${_claim#Never says: }
                jq -r --arg p "Part $_part: " '.tests[] | select(.name | startswith($p)) | .output' "$_json" >"$_tmp" 2>/dev/null
                [ -s "$_tmp" ] && ! grep -qF -- "$_text" "$_tmp" ;;
        esac
        if [ $? = 0 ]; then echo "  ok    $(basename "$_patch" .patch): $_claim"
        else echo "  FAIL  $(basename "$_patch" .patch): $_claim"; _bad=1; fi
    done <<EOF
$_claims
EOF
    rm -f "$_tmp"
    return $_bad
}
