/* gud = cycle600(_INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X, _POS_Y, _POS_Z, _ANG_1, _ANG_2,
 * _ANG_3, _POS_X_R, _POS_Y_R, _POS_Z_R, _INEXOUT, _BIN_OUT, _ROT_AD, _ROT_INV, _RETR_Z
 * [, previous gud]): see cycle600.m. */
#include "gateway.h"

static const char *FIELDS[] = {"CYC600_1", "CYC600_2", "CYC600_3", "CYC600_4", "CYC600_5",
                               "CYC600_6", "frame",    "ROT_INV",  "RETR_Z",   "CHECKSUM"};
#define NFIELDS (sizeof FIELDS / sizeof FIELDS[0])

static const mxArray *field(const mxArray *s, const char *name) {
  const mxArray *f = mxGetField(s, 0, name);
  if (f == NULL) mexErrMsgIdAndTxt("cncrot:badState", "previous gud lacks field %s (not a struct returned by cycle600)", name);
  return f;
}

/* The C state from a struct returned by an earlier call: every field as it was returned,
 * and its CHECKSUM, which the library verifies (an edited field is refused as badState). */
static void gud_from_struct(const mxArray *s, cncrot_cycle600_gud *g) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    mexErrMsgIdAndTxt("cncrot:badClass", "previous gud must be a struct returned by cycle600");
  memset(g, 0, sizeof *g);
  char name[33];
  name_arg(field(s, "CYC600_1"), "CYC600_1", name);
  if (strlen(name) >= sizeof g->cyc600_1)
    mexErrMsgIdAndTxt("cncrot:badState", "CYC600_1 is longer than 31 characters");
  memcpy(g->cyc600_1, name, strlen(name));
  g->cyc600_2 = scalar_arg(field(s, "CYC600_2"), "CYC600_2");
  g->cyc600_3 = scalar_arg(field(s, "CYC600_3"), "CYC600_3");
  g->cyc600_4 = scalar_arg(field(s, "CYC600_4"), "CYC600_4");
  g->cyc600_5 = integer_arg(field(s, "CYC600_5"), "CYC600_5");
  g->cyc600_6 = integer_arg(field(s, "CYC600_6"), "CYC600_6");
  const mxArray *f = field(s, "frame");
  const double *fd = real_data(f, "frame");
  if (mxGetNumberOfDimensions(f) != 2 || mxGetM(f) != 4 || mxGetN(f) != 4)
    mexErrMsgIdAndTxt("cncrot:badSize", "frame must be 4-by-4");
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) g->frame[4 * i + j] = fd[i + 4 * j];
  g->rot_inv = integer_arg(field(s, "ROT_INV"), "ROT_INV");
  g->retr_z = integer_arg(field(s, "RETR_Z"), "RETR_Z");
  double c = scalar_arg(field(s, "CHECKSUM"), "CHECKSUM");
  if (!(c >= 0 && c <= 4294967295.0 && c == floor(c)))
    mexErrMsgIdAndTxt("cncrot:badState", "CHECKSUM is not a 32-bit checksum");
  g->checksum = (uint32_t)c;
  g->active = 1;
  g->format = CNCROT_CYCLE600_GUD_FORMAT;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  check_nargs(nrhs, 18, 19, nlhs, 1);
  char name[33];
  name_arg(prhs[1], "_MIHEAD", name);
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
  if (s < 0) raise_status(s, -1, 0);
  mxArray *out = mxCreateStructMatrix(1, 1, (int)NFIELDS, FIELDS);
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
  mxSetField(out, 0, "CHECKSUM", mxCreateDoubleScalar(gud.checksum));
  plhs[0] = out;
}
