/* [text, remarks, state] = cncrot_program_translate(dialect, lines, to, form, decimals): see
 * cncrot_program_translate.m. */
#include "program_state.h"

/* What the target writes for a block, with the block's skip mark on each of its lines (an
 * optional block stays optional): "/", or an ISO level "/2 " between ISO-style dialects
 * (Heidenhain has one mark, and its digits after "/" are the block number). `keep` (the
 * block's other words, cncrot_program_rest, with the block's own mark) comes first. */
static mxArray *skip_marked(const char *block, size_t len, int32_t from, int32_t to, const char *keep,
                            const char *out) {
  size_t i = 0;
  while (i < len && (block[i] == ' ' || block[i] == '\t')) i++;
  char mark[16] = "";
  if (i < len && block[i] == '/') {
    size_t d = i + 1, n = 0;
    mark[0] = '/';
    while (d < len && block[d] >= '0' && block[d] <= '9' && n < 8) mark[1 + n++] = block[d++];
    int iso = from != CNCROT_DIALECT_HEIDENHAIN && to != CNCROT_DIALECT_HEIDENHAIN;
    if (iso && n > 0) {
      mark[1 + n] = ' ';
      mark[2 + n] = '\0';
    } else {
      mark[1] = '\0';
    }
  }
  static char marked[3 * CNCROT_PROGRAM_CHANGE_MAX + 64];
  size_t m = 0, ml = strlen(mark);
  for (const char *o = keep; *o && m + 2 < sizeof marked; o++) marked[m++] = *o;
  if (m > 0 && out[0]) marked[m++] = '\n';
  int start = 1;
  for (const char *o = out; *o && m + ml + 2 < sizeof marked; o++) {
    if (start) {
      memcpy(marked + m, mark, ml);
      m += ml;
    }
    marked[m++] = *o;
    start = *o == '\n';
  }
  marked[m] = '\0';
  return mxCreateString(marked);
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 4, 5, nlhs, 3);
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  int32_t to = dialect_arg(prhs[2], 3, "to");
  char form[65];
  form_name_arg(prhs[3], 4, form);
  int32_t decimals = nrhs > 4 ? integer_arg(prhs[4], 5, "decimals") : -1;
  cncrot_program p;
  memset(&p, 0, sizeof p);
  static char out[CNCROT_PROGRAM_CHANGE_MAX + 1];
  /* The form and the decimals are judged before any line: no change, the same statuses. */
  int32_t s = cncrot_program_write_change(&p, &p, to, form, decimals, out, sizeof out);
  if (s < 0) {
    if (s == CNCROT_STATUS_BAD_ARGUMENT && decimals > 17)
      fail("cncrot:badArgument", "%s must be 0..17, or negative for the shortest numbers that read back exactly; got %d",
           label(5, "decimals"), (int)decimals);
    raise_at(s, label(4, "form"), NULL, -1, 0);
  }
  const mxArray *lines = lines_arg(prhs[1], 2);
  int cell = mxIsCell(lines);
  size_t n = cell ? mxGetNumberOfElements(lines) : 1;
  mxArray *text = mxCreateCellMatrix(n, 1);
  mxArray *remarks = mxCreateCellMatrix(n, 1);
  /* Blocks that are one command spread over lines (cycle 7's axis lines, a tilt and its turn)
   * are written as one change at the last of them: the state before the first. */
  cncrot_program run;
  int running = 0;
  for (size_t k = 0; k < n; k++) {
    const mxArray *a = cell ? mxGetCell(lines, k) : lines;
    if (!a) a = mxCreateString("");
    char buf[CNCROT_PROGRAM_LINE_MAX + 3];
    size_t len = line_bytes(a, 2, buf, sizeof buf);
    cncrot_program before = p;
    s = cncrot_program_line(&p, dialect, buf, len);
    if (s < 0) {
      mxDestroyArray(text);
      mxDestroyArray(remarks);
      raise_line(s, &p, dialect, buf, len, 2, k, n);
    }
    if (s == CNCROT_STATUS_PASSED || s == CNCROT_STATUS_NOT_FOLLOWED) {
      /* Not about the frame, or not followed: the block as it stands. */
      buf[len] = '\0';
      mxSetCell(text, k, mxIsChar(a) ? mxDuplicateArray(a) : mxCreateString(buf));
      mxSetCell(remarks, k, mxCreateString(s == CNCROT_STATUS_PASSED ? "passed" : "not followed"));
      continue;
    }
    /* The block's other words (a retract beside a cancel, the motion mode and feed beside a
     * tilt), kept as they stand before its translation. */
    char keep[CNCROT_PROGRAM_LINE_MAX + 3] = "";
    if (to != dialect && cncrot_program_rest(dialect, buf, len, keep, sizeof keep) != CNCROT_STATUS_OK) keep[0] = '\0';
    if (to != dialect && cell && k + 1 < n && mxGetCell(lines, k + 1)) {
      char next_buf[CNCROT_PROGRAM_LINE_MAX + 3];
      size_t next_len = line_bytes(mxGetCell(lines, k + 1), 2, next_buf, sizeof next_buf);
      cncrot_program next = p;
      int32_t join = 0;
      if (cncrot_program_line(&next, dialect, next_buf, next_len) == CNCROT_STATUS_OK &&
          cncrot_program_joins(&before, &p, &next, &join) == CNCROT_STATUS_OK && join) {
        /* Written with the next block. */
        if (!running) run = before;
        running = 1;
        mxSetCell(text, k, mxCreateString(keep));
        mxSetCell(remarks, k, mxCreateString("applied"));
        continue;
      }
    }
    cncrot_program from = running ? run : before;
    running = 0;
    /* Into another dialect also what the block restates (a cancel, a datum shift, with
     * nothing active: the control may have something active). */
    int32_t w = to == dialect ? cncrot_program_write_change(&before, &p, to, form, decimals, out, sizeof out)
                              : cncrot_program_write_block(&from, &p, buf, len, to, form, decimals, out, sizeof out);
    if (w < 0) {
      mxDestroyArray(text);
      mxDestroyArray(remarks);
      /* The target cannot say this change: the line it came from. */
      char where[80];
      snprintf(where, sizeof where, "%s, line %d", label(2, "lines"), (int)(k + 1));
      raise_at(w, where, NULL, -1, 0);
    }
    /* A plane selected (G18, perhaps with a move) writes nothing: the block as it stands. */
    if (out[0] == '\0' && before.plane != p.plane) {
      buf[len] = '\0';
      mxSetCell(text, k, mxIsChar(a) ? mxDuplicateArray(a) : mxCreateString(buf));
    } else {
      mxSetCell(text, k, skip_marked(buf, len, dialect, to, keep, out));
    }
    mxSetCell(remarks, k, mxCreateString("applied"));
  }
  plhs[0] = text;
  if (nlhs > 1) plhs[1] = remarks; else mxDestroyArray(remarks);
  if (nlhs > 2) plhs[2] = to_struct(&p);
}
