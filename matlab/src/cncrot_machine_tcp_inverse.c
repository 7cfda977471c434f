/* [axes, status] = cncrot_machine_tcp_inverse(machine, P, L, previous, rule, ref):
 * see cncrot_machine_tcp_inverse.m. */
#include <math.h>
#include "gateway.h"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 3, 6, nlhs, 2);
  cncrot_machine m;
  machine_arg(prhs[0], 1, &m);
  /* Poses 4-by-4-by-N, or CL rows N-by-6 (x y z i j k). */
  const mxArray *p = prhs[1];
  (void)real_data(p, 2, "P");
  const mwSize *d = mxGetDimensions(p);
  int cl = mxGetNumberOfDimensions(p) == 2 && d[1] == 6;
  size_t n = cl ? rows_arg(p, 2, "P", 6) : squares_arg(p, 2, "P", 4);
  const double *pd = real_data(p, 2, "P");
  double len = finite_arg(scalar_arg(prhs[2], 3, "L"), 3, "L");
  double prev[6] = {0, 0, 0, 0, 0, 0};
  if (nrhs > 3) previous_arg(prhs[3], 4, prev);
  int32_t rule = nrhs > 4 ? rule_arg(prhs[4], 5, "rule") : CNCROT_CHOOSE_CLOSEST;
  int32_t ref = nrhs > 5 ? integer_arg(prhs[5], 6, "ref") : 0;
  rule_ref_check(rule, ref, m.count, 6);
  mxArray *out = mxCreateDoubleMatrix(n, 6, mxREAL);
  mxArray *st = mxCreateDoubleMatrix(n, 1, mxREAL);
  double *o = mxGetDoubles(out), *so = mxGetDoubles(st);
  for (size_t r = 0; r < n; r++) {
    double f[16], ax[6];
    if (cl) {
      double tip[3] = {pd[r], pd[r + n], pd[r + 2 * n]}, dir[3] = {pd[r + 3 * n], pd[r + 4 * n], pd[r + 5 * n]};
      /* The library's pose of a CL point, as `cncrot path` takes it: with three rotary
         axes carried from the orientation where the machine stands (the turn about the
         tool continuous, no jump where cncrot_cl_pose changes its X'). */
      double before[16];
      int32_t c = m.count == 3 && cncrot_machine_forward(&m, prev + 3, before) == CNCROT_STATUS_OK
                      ? cncrot_cl_pose_toward(tip, dir, before, f)
                      : cncrot_cl_pose(tip, dir, f);
      if (c == CNCROT_STATUS_DEGENERATE) {
        mxDestroyArray(out);
        mxDestroyArray(st);
        if (n > 1)
          fail("cncrot:badArgument", "%s, row %d: the tool direction (i, j, k) must not be zero", label(2, "P"), (int)r + 1);
        fail("cncrot:badArgument", "%s: the tool direction (i, j, k) must not be zero", label(2, "P"));
      }
      if (c < 0) {
        mxDestroyArray(out);
        mxDestroyArray(st);
        raise_status(c, label(2, "P"), "row", (long)r, n);
      }
    } else {
      frame_to_row_major(pd + 16 * r, f);
    }
    int32_t s = cncrot_machine_tcp_inverse_rule(&m, f, len, prev, rule, ref, ax);
    if (s < 0) {
      mxDestroyArray(out);
      mxDestroyArray(st);
      const char *where = s == CNCROT_STATUS_BAD_ARGUMENT || (s == CNCROT_STATUS_OUT_OF_RANGE && len >= -1e6 && len <= 1e6)
                              ? (r == 0 ? label(4, "previous") : label(2, "P"))
                          : s == CNCROT_STATUS_OUT_OF_RANGE ? label(3, "L")
                                                            : label(2, "P");
      raise_status(s, where, "row", (long)r, n);
    }
    for (int c = 0; c < 6; c++) o[r + n * c] = ax[c];
    so[r] = s;
    memcpy(prev, ax, sizeof prev);
    /* The rule picks the first row's solution; the rows after it continue from it (a
       priority axis' side or direction taken again at each row would swap branches where
       that axis passes 0, and the other solution every row). */
    rule = CNCROT_CHOOSE_CLOSEST, ref = 0;
  }
  plhs[0] = out;
  if (nlhs > 1)
    plhs[1] = st;
  else
    mxDestroyArray(st);
}
