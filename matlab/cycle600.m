% CYCLE600  The paper's cycle CYCLE600 (recalculation of rotations), on the C library.
%   gud = cycle600(INEXIN, MIHEAD, SW_REC, BIN_IN, POS_X, POS_Y, POS_Z, ANG_1, ANG_2, ANG_3,
%                  POS_X_R, POS_Y_R, POS_Z_R, INEXOUT, BIN_OUT, ROT_AD, ROT_INV, RETR_Z)
%   gud = cycle600(..., previous_gud)   % ROT_AD = 1 adds to previous_gud's frame
%   The 18 parameters of the paper in its order (_INEXIN ... _RETR_Z). INEXIN and INEXOUT
%   are 'intrinsic' or 'extrinsic' (or 1 or 0), BIN_IN and BIN_OUT axis sequences as in
%   CNCROT_MATRIX ('XYZ', 'ZXY', or the codes 57, 39; BIN_OUT with three rotations);
%   SW_REC, ROT_AD, ROT_INV, RETR_Z are 0 or 1 (or false or true). Integers may be of any
%   numeric class. MIHEAD is text (char or string) of printable ASCII without spaces or
%   quotes (at most 31 characters). gud has fields CYC600_1 (name), CYC600_2..4 (angles,
%   degrees), CYC600_5 (_INEXOUT), CYC600_6 (_BIN_OUT), frame (4-by-4, translations
%   included), ROT_INV, RETR_Z and CHECKSUM (the CRC-32 of the state). Pass gud back
%   unchanged: an edited field no longer matches CHECKSUM and raises cncrot:badState, as a
%   corrupt stored state does.
%   SW_REC = 0 (positioning the head) recalculates exactly as SW_REC = 1 does (it raises no
%   error); the axis positions for the head are then those of
%   cncrot_machine_choose(machine, gud.frame, current, 'closest'), or 'inverse' with
%   ROT_INV = 1 (what the C library's cncrot_cycle600_position gives).
%   Errors name the argument ("cycle600: argument 17 (_ROT_INV) must be 0 or 1 ...").
%
%   Example (the paper's Example 3):
%     gud = cycle600('extrinsic', 'UFK600', 1, 'XYZ', 0,0,0, 30,45,60, 0,0,0, 'intrinsic', 'ZXY', 0,0,0);
%     [gud.CYC600_2 gud.CYC600_3 gud.CYC600_4]   % 37.7923 20.7048 49.1066
%     % the same as cycle600(0, 'UFK600', 1, 57, 0,0,0, 30,45,60, 0,0,0, 1, 39, 0,0,0)
%
%   See also CNCROT_CONVERT, CNCROT_MATRIX, CNCROT_MACHINE_CHOOSE.
