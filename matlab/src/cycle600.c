/* gud = cycle600(_INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X, _POS_Y, _POS_Z, _ANG_1, _ANG_2,
 * _ANG_3, _POS_X_R, _POS_Y_R, _POS_Z_R, _INEXOUT, _BIN_OUT, _ROT_AD, _ROT_INV, _RETR_Z
 * [, previous gud]): see cycle600.m. */
#include "gateway.h"

static const char *FIELDS[] = {"CYC600_1", "CYC600_2", "CYC600_3", "CYC600_4", "CYC600_5",
                               "CYC600_6", "frame",    "ROT_INV",  "RETR_Z"};

static const mxArray *field(const mxArray *s, const char *name) {
  const mxArray *f = mxGetField(s, 0, name);
  if (f == NULL) mexErrMsgIdAndTxt("cncrot:badArgument", "previous gud lacks field %s", name);
  return f;
}

/* The C state from a struct returned by an earlier call. */
static void gud_from_struct(const mxArray *s, cncrot_cycle600_gud *g) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    mexErrMsgIdAndTxt("cncrot:badClass", "previous gud must be a struct returned by cycle600");
  memset(g, 0, sizeof *g);
  const mxArray *name = field(s, "CYC600_1");
  if (!mxIsChar(name) || mxGetString(name, g->cyc600_1, sizeof g->cyc600_1) != 0)
    mexErrMsgIdAndTxt("cncrot:nameTooLong", "CYC600_1 must be a name of at most 31 characters");
  g->cyc600_2 = scalar_arg(field(s, "CYC600_2"), "CYC600_2");
  g->cyc600_3 = scalar_arg(field(s, "CYC600_3"), "CYC600_3");
  g->cyc600_4 = scalar_arg(field(s, "CYC600_4"), "CYC600_4");
  g->cyc600_5 = integer_arg(field(s, "CYC600_5"), "CYC600_5");
  g->cyc600_6 = integer_arg(field(s, "CYC600_6"), "CYC600_6");
  const mxArray *f = field(s, "frame");
  require_real_double(f, "frame");
  if (mxGetM(f) != 4 || mxGetN(f) != 4) mexErrMsgIdAndTxt("cncrot:badSize", "frame must be 4-by-4");
  const double *fd = mxGetDoubles(f);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) g->frame[4 * i + j] = fd[i + 4 * j];
  g->rot_inv = integer_arg(field(s, "ROT_INV"), "ROT_INV");
  g->retr_z = integer_arg(field(s, "RETR_Z"), "RETR_Z");
  g->active = 1;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 18, 19, nlhs, 1);
  if (!mxIsChar(prhs[1])) mexErrMsgIdAndTxt("cncrot:badClass", "_MIHEAD must be a char array");
  char name[64];
  if (mxGetString(prhs[1], name, sizeof name) != 0)
    mexErrMsgIdAndTxt("cncrot:nameTooLong", "_MIHEAD is longer than 31 characters");
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  if (nrhs == 19) gud_from_struct(prhs[18], &gud);
  int32_t s = cncrot_cycle600(
      &gud, NULL, integer_arg(prhs[0], "_INEXIN"), name, integer_arg(prhs[2], "_SW_REC"),
      integer_arg(prhs[3], "_BIN_IN"), scalar_arg(prhs[4], "_POS_X"), scalar_arg(prhs[5], "_POS_Y"),
      scalar_arg(prhs[6], "_POS_Z"), scalar_arg(prhs[7], "_ANG_1"), scalar_arg(prhs[8], "_ANG_2"),
      scalar_arg(prhs[9], "_ANG_3"), scalar_arg(prhs[10], "_POS_X_R"), scalar_arg(prhs[11], "_POS_Y_R"),
      scalar_arg(prhs[12], "_POS_Z_R"), integer_arg(prhs[13], "_INEXOUT"), integer_arg(prhs[14], "_BIN_OUT"),
      integer_arg(prhs[15], "_ROT_AD"), integer_arg(prhs[16], "_ROT_INV"), integer_arg(prhs[17], "_RETR_Z"));
  if (s < 0) raise_status(s, 0);
  mxArray *out = mxCreateStructMatrix(1, 1, 9, FIELDS);
  mxSetField(out, 0, "CYC600_1", mxCreateString(gud.cyc600_1));
  mxSetField(out, 0, "CYC600_2", mxCreateDoubleScalar(gud.cyc600_2));
  mxSetField(out, 0, "CYC600_3", mxCreateDoubleScalar(gud.cyc600_3));
  mxSetField(out, 0, "CYC600_4", mxCreateDoubleScalar(gud.cyc600_4));
  mxSetField(out, 0, "CYC600_5", mxCreateDoubleScalar(gud.cyc600_5));
  mxSetField(out, 0, "CYC600_6", mxCreateDoubleScalar(gud.cyc600_6));
  mxArray *frame = mxCreateDoubleMatrix(4, 4, mxREAL);
  double *fd = mxGetDoubles(frame);
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) fd[i + 4 * j] = gud.frame[4 * i + j];
  mxSetField(out, 0, "frame", frame);
  mxSetField(out, 0, "ROT_INV", mxCreateDoubleScalar(gud.rot_inv));
  mxSetField(out, 0, "RETR_Z", mxCreateDoubleScalar(gud.retr_z));
  plhs[0] = out;
}
