/* [F, state, frames, remarks] = cncrot_program_lines(dialect, lines, state): see
 * cncrot_program_lines.m. */
#include "program_state.h"

/* One line of text as bytes (characters beyond ASCII become a byte every dialect refuses):
 * a char row vector or a string scalar. */
static size_t line_bytes(const mxArray *a, char *out, size_t cap) {
  size_t n = 0;
  const mxChar *c = chars_of(a, 2, "lines", &n);
  if (c == NULL)
    fail("cncrot:badClass", "%s must be text (char, a string, or a cell array of them); got %s", label(2, "lines"), described(a));
  size_t k;
  /* Longer lines than any dialect reads arrive cut to cap bytes: the library refuses them. */
  for (k = 0; k < n && k < cap; k++) out[k] = ascii_byte(c[k]);
  return k;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 3, nlhs, 4);
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  cncrot_program p;
  if (nrhs == 3) from_struct(prhs[2], 3, &p);
  else memset(&p, 0, sizeof p);
  const mxArray *lines = prhs[1];
  if (mxIsClass(lines, "string") && mxGetNumberOfElements(lines) != 1) {
    /* A string array: its elements as a cell array of char, by MATLAB's cellstr. */
    mxArray *cells = NULL, *in = (mxArray *)lines;
    if (mexCallMATLABWithTrap(1, &cells, 1, &in, "cellstr") != NULL || cells == NULL)
      fail("cncrot:badClass", "%s: the strings could not be read (a missing string?)", label(2, "lines"));
    lines = cells;
  }
  int cell = mxIsCell(lines);
  size_t n = cell ? mxGetNumberOfElements(lines) : 1;
  mxArray *frames = mxCreateNumericArray(3, (mwSize[]){4, 4, n}, mxDOUBLE_CLASS, mxREAL);
  /* What each block did: 'applied', 'passed' (not about the frame), 'not followed'. */
  mxArray *remarks = mxCreateCellMatrix(n, 1);
  double *fr = mxGetDoubles(frames);
  double f[16];
  /* The state's own check, also for no lines. */
  int32_t s = cncrot_program_frame(&p, f);
  if (s < 0) {
    mxDestroyArray(frames);
    raise_at(s, label(3, "state"), NULL, -1, 0);
  }
  for (size_t k = 0; k < n; k++) {
    const mxArray *a = cell ? mxGetCell(lines, k) : lines;
    if (!a) a = mxCreateString("");
    char buf[CNCROT_PROGRAM_LINE_MAX + 3];
    size_t len = line_bytes(a, buf, sizeof buf);
    size_t column = 0;
    s = cncrot_program_line(&p, dialect, buf, len);
    if (s < 0) {
      char what[CNCROT_PROGRAM_EXPECTED_SIZE];
      cncrot_program_column(&p, dialect, buf, len, &column);
      cncrot_program_expected(&p, dialect, buf, len, what, sizeof what);
      mxDestroyArray(frames);
      mxDestroyArray(remarks);
      char where[96 + CNCROT_PROGRAM_EXPECTED_SIZE + 48];
      if (column > 0) {
        int at = snprintf(where, sizeof where, "%s, line %d, column %d", label(2, "lines"), (int)(k + 1), (int)column);
        /* The word the reader wanted, or the word it could not use. */
        if (what[0] && at > 0 && (size_t)at < sizeof where) {
          snprintf(where + at, sizeof where - (size_t)at, " (%s%s)", s == CNCROT_STATUS_MISSING_WORD ? "missing: " : "",
                   what);
        } else if (column <= len && at > 0 && (size_t)at < sizeof where) {
          size_t end = column - 1;
          while (end < len && end < column - 1 + 24 && buf[end] != ' ' && buf[end] != '\t') end++;
          snprintf(where + at, sizeof where - (size_t)at, " ('%.*s')", (int)(end - (column - 1)), buf + column - 1);
        }
        raise_at(s, where, NULL, -1, 0);
      }
      raise_at(s, label(2, "lines"), "line", (long)k, n);
    }
    mxSetCell(remarks, k,
              mxCreateString(s == CNCROT_STATUS_PASSED         ? "passed"
                             : s == CNCROT_STATUS_NOT_FOLLOWED ? "not followed"
                                                               : "applied"));
    cncrot_program_frame(&p, f);
    frame_to_col_major(f, fr + 16 * k);
  }
  mxArray *F = mxCreateDoubleMatrix(4, 4, mxREAL);
  frame_to_col_major(f, mxGetDoubles(F));
  plhs[0] = F;
  if (nlhs > 1) plhs[1] = to_struct(&p);
  if (nlhs > 2) plhs[2] = frames; else mxDestroyArray(frames);
  if (nlhs > 3) plhs[3] = remarks; else mxDestroyArray(remarks);
}
