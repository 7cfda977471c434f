% CYCLE600  The paper's cycle CYCLE600 (recalculation of rotations), on the C library.
%   gud = cycle600(INEXIN, MIHEAD, SW_REC, BIN_IN, POS_X, POS_Y, POS_Z, ANG_1, ANG_2, ANG_3,
%                  POS_X_R, POS_Y_R, POS_Z_R, INEXOUT, BIN_OUT, ROT_AD, ROT_INV, RETR_Z)
%   gud = cycle600(..., previous_gud)   % ROT_AD = 1 adds to previous_gud's frame
%   The 18 parameters of the paper in its order (_INEXIN ... _RETR_Z); MIHEAD is a char
%   row vector of printable ASCII without spaces (at most 31 characters). gud has fields
%   CYC600_1 (name), CYC600_2..4 (angles, degrees), CYC600_5 (_INEXOUT), CYC600_6
%   (_BIN_OUT), frame (4-by-4, translations included), ROT_INV, RETR_Z and CHECKSUM (the
%   CRC-32 of the state). Pass gud back unchanged: an edited field no longer matches
%   CHECKSUM and raises cncrot:badState, as a corrupt stored state does.
%   SW_REC = 0 (positioning the head) raises cncrot:notAvailable.
%
%   Example (the paper's Example 3):
%     gud = cycle600(0, 'UFK600', 1, 57, 0,0,0, 30,45,60, 0,0,0, 1, 39, 0,0,0);
%     [gud.CYC600_2 gud.CYC600_3 gud.CYC600_4]   % 37.7923 20.7048 49.1066
