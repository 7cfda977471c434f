/* [F, state, frames, remarks] = cncrot_program_lines(dialect, lines, state, machine): see
 * cncrot_program_lines.m. */
#include "program_state.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 2, 4, nlhs, 4);
  int32_t dialect = dialect_arg(prhs[0], 1, "dialect");
  cncrot_program p;
  if (nrhs >= 3) from_struct(prhs[2], 3, &p);
  else memset(&p, 0, sizeof p);
  cncrot_machine m;
  const cncrot_machine *mp = NULL;
  if (nrhs == 4) {
    machine_arg(prhs[3], 4, &m);
    mp = &m;
  }
  const mxArray *lines = lines_arg(prhs[1], 2);
  int cell = mxIsCell(lines);
  size_t n = cell ? mxGetNumberOfElements(lines) : 1;
  mxArray *frames = mxCreateNumericArray(3, (mwSize[]){4, 4, n}, mxDOUBLE_CLASS, mxREAL);
  /* What each block did: 'applied', 'passed' (not about the frame), 'not followed'. */
  mxArray *remarks = mxCreateCellMatrix(n, 1);
  double *fr = mxGetDoubles(frames);
  double f[16];
  /* The state's own check, also for no lines. */
  int32_t s = frame_of(&p, mp, f);
  if (s < 0) {
    mxDestroyArray(frames);
    mxDestroyArray(remarks);
    raise_at(s, s == CNCROT_STATUS_BAD_STATE ? label(3, "state") : label(4, "machine"), NULL, -1, 0);
  }
  for (size_t k = 0; k < n; k++) {
    const mxArray *a = cell ? mxGetCell(lines, k) : lines;
    if (!a) a = mxCreateString("");
    char buf[CNCROT_PROGRAM_LINE_MAX + 3];
    size_t len = line_bytes(a, 2, buf, sizeof buf);
    s = cncrot_program_line(&p, dialect, buf, len);
    if (s < 0) {
      mxDestroyArray(frames);
      mxDestroyArray(remarks);
      raise_line(s, &p, dialect, buf, len, 2, k, n);
    }
    mxSetCell(remarks, k,
              mxCreateString(s == CNCROT_STATUS_PASSED         ? "passed"
                             : s == CNCROT_STATUS_NOT_FOLLOWED ? "not followed"
                                                               : "applied"));
    s = frame_of(&p, mp, f);
    if (s < 0) {
      /* The machine cannot give this block's frame (a position for an axis it lacks). */
      mxDestroyArray(frames);
      mxDestroyArray(remarks);
      char where[160];
      snprintf(where, sizeof where, "%s, line %d: its frame on %s", label(2, "lines"), (int)(k + 1),
               label(4, "machine"));
      raise_at(s, where, NULL, -1, 0);
    }
    frame_to_col_major(f, fr + 16 * k);
  }
  mxArray *F = mxCreateDoubleMatrix(4, 4, mxREAL);
  frame_to_col_major(f, mxGetDoubles(F));
  plhs[0] = F;
  if (nlhs > 1) plhs[1] = to_struct(&p);
  if (nlhs > 2) plhs[2] = frames; else mxDestroyArray(frames);
  if (nlhs > 3) plhs[3] = remarks; else mxDestroyArray(remarks);
}
