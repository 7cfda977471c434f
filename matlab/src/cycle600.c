/* gud = cycle600(_INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X, _POS_Y, _POS_Z, _ANG_1, _ANG_2,
 * _ANG_3, _POS_X_R, _POS_Y_R, _POS_Z_R, _INEXOUT, _BIN_OUT, _ROT_AD, _ROT_INV, _RETR_Z
 * [, previous gud]): see cycle600.m. */
#include "gateway.h"

static const char *FIELDS[] = {"CYC600_1", "CYC600_2", "CYC600_3", "CYC600_4", "CYC600_5",
                               "CYC600_6", "frame",    "ROT_INV",  "RETR_Z",   "CHECKSUM"};
#define NFIELDS (sizeof FIELDS / sizeof FIELDS[0])

#define GUD_ARG 19

static const mxArray *field(const mxArray *s, const char *name) {
  const mxArray *f = mxGetField(s, 0, name);
  if (f == NULL)
    fail("cncrot:badState", "%s lacks field %s (not a struct returned by cycle600)", label(GUD_ARG, "previous gud"), name);
  return f;
}

/* "previous gud.CYC600_5", for messages about a field. */
static const char *field_label(const char *name) {
  static char buf[64];
  snprintf(buf, sizeof buf, "argument %d (previous gud), field %s", GUD_ARG, name);
  return buf;
}

/* The C state from a struct returned by an earlier call: every field as it was returned,
 * and its CHECKSUM, which the library verifies (an edited field is refused as badState). */
static void gud_from_struct(const mxArray *s, cncrot_cycle600_gud *g) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    fail("cncrot:badClass", "%s must be a struct returned by cycle600; got %s", label(GUD_ARG, "previous gud"), described(s));
  memset(g, 0, sizeof *g);
  char name[33];
  name_arg(field(s, "CYC600_1"), 0, field_label("CYC600_1"), name);
  if (strlen(name) >= sizeof g->cyc600_1) fail("cncrot:badState", "%s is longer than 31 characters", field_label("CYC600_1"));
  memcpy(g->cyc600_1, name, strlen(name));
  g->cyc600_2 = scalar_arg(field(s, "CYC600_2"), 0, field_label("CYC600_2"));
  g->cyc600_3 = scalar_arg(field(s, "CYC600_3"), 0, field_label("CYC600_3"));
  g->cyc600_4 = scalar_arg(field(s, "CYC600_4"), 0, field_label("CYC600_4"));
  g->cyc600_5 = integer_arg(field(s, "CYC600_5"), 0, field_label("CYC600_5"));
  g->cyc600_6 = integer_arg(field(s, "CYC600_6"), 0, field_label("CYC600_6"));
  const mxArray *f = field(s, "frame");
  const double *fd = real_data(f, 0, field_label("frame"));
  if (mxGetNumberOfDimensions(f) != 2 || mxGetM(f) != 4 || mxGetN(f) != 4)
    fail("cncrot:badSize", "%s must be 4-by-4", field_label("frame"));
  frame_to_row_major(fd, g->frame);
  g->rot_inv = integer_arg(field(s, "ROT_INV"), 0, field_label("ROT_INV"));
  g->retr_z = integer_arg(field(s, "RETR_Z"), 0, field_label("RETR_Z"));
  double c = scalar_arg(field(s, "CHECKSUM"), 0, field_label("CHECKSUM"));
  if (!(c >= 0 && c <= 4294967295.0 && c == floor(c))) fail("cncrot:badState", "%s is not a 32-bit checksum", field_label("CHECKSUM"));
  g->checksum = (uint32_t)c;
  g->active = 1;
  g->format = CNCROT_CYCLE600_GUD_FORMAT;
}

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[]) {
  static const char *POS[9] = {"_POS_X", "_POS_Y", "_POS_Z", "_ANG_1", "_ANG_2", "_ANG_3", "_POS_X_R", "_POS_Y_R", "_POS_Z_R"};
  check_nargs(nrhs, 18, 19, nlhs, 1);
  /* Every argument in the paper's order, so that the first wrong one is named. */
  int32_t inexin = convention_arg(prhs[0], 1, "_INEXIN");
  char name[33];
  name_arg(prhs[1], 2, "_MIHEAD", name);
  int32_t sw_rec = switch_arg(prhs[2], 3, "_SW_REC");
  int32_t bin_in = sequence_arg(prhs[3], 4, "_BIN_IN", 0);
  double v[9];
  for (int k = 0; k < 9; k++) v[k] = scalar_arg(prhs[4 + k], 5 + k, POS[k]);
  int32_t inexout = convention_arg(prhs[13], 14, "_INEXOUT");
  int32_t bin_out = sequence_arg(prhs[14], 15, "_BIN_OUT", 1);
  int32_t rot_ad = switch_arg(prhs[15], 16, "_ROT_AD");
  int32_t rot_inv = switch_arg(prhs[16], 17, "_ROT_INV");
  int32_t retr_z = switch_arg(prhs[17], 18, "_RETR_Z");
  cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  if (nrhs == 19) gud_from_struct(prhs[18], &gud);
  int32_t s = cncrot_cycle600(&gud, NULL, inexin, name, sw_rec, bin_in, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8],
                              inexout, bin_out, rot_ad, rot_inv, retr_z);
  if (s < 0) {
    const char *where = NULL;
    if (s == CNCROT_STATUS_NAME_TOO_LONG || s == CNCROT_STATUS_BAD_ARGUMENT) where = label(2, "_MIHEAD");
    else if (s == CNCROT_STATUS_BAD_STATE) where = label(GUD_ARG, "previous gud");
    else if (s == CNCROT_STATUS_NOT_FINITE || s == CNCROT_STATUS_OUT_OF_RANGE)
      where = "the positions and angles (arguments 5 to 13, _POS_X .. _POS_Z_R)";
    raise_at(s, where, NULL, -1, 0);
  }
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
