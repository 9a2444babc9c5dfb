/* Test machinery: not part of any assignment. The grader's suite: make test-grader. */
int verdict_tests(void);
int sandbox_tests(void);
int split_tests(void);
int readers_tests(void);  /* references, cases, suite results read as hostile; the score */
int words_tests(void);  /* what the grader writes: words, results.json, the report, facts.json */
int allow_tests(void);  /* the allow-list, the PL_PART_API marks and the handout agree */
int figure_tests(void);  /* what reaches the student: figures rounded, hidden cases coarse */
int manifest_tests(void);  /* a submitted part's folder, read as data before anything builds it */
int inspect_tests(void);  /* the object inspection, attacked one rule at a time */
int layout_tests(void);  /* grader/README.md's rules, checked on the sources */

int main(void)
{
    int failed = verdict_tests();
    failed += sandbox_tests();
    failed += split_tests();
    failed += readers_tests();
    failed += words_tests();
    failed += allow_tests();
    failed += figure_tests();
    failed += manifest_tests();
    failed += inspect_tests();
    failed += layout_tests();
    return failed != 0;
}
