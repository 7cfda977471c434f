% CNCROT_MATRIX  Rotation matrices from angles (degrees).
%   R = cncrot_matrix(intrinsic, sequence, angles)
%   intrinsic: 'intrinsic' (or 'i', or 1) about the rotated workpiece axes,
%   R = R_a1*R_a2*R_a3; 'extrinsic' (or 'e', or 0) about the fixed machine axes,
%   R = R_a3*R_a2*R_a1.
%   sequence: the axes in rotation order, 'XYZ', 'ZXY', "ZX'Y''" (primes are ignored), with
%   '0' for a skipped rotation ('X0Z'); or the code a1 + 4*a2 + 16*a3 with X=1, Y=2, Z=3,
%   none=0 (57 = 'XYZ', 39 = 'ZXY', 49 = 'X0Z'). Names are case-insensitive, char or string;
%   a number may be of any numeric class or logical, and must be an integer.
%   angles: N-by-3, degrees, in rotation order (N may be 0: zeros(0,3) or [] give a
%   3-by-3-by-0 result). R: 3-by-3 (N = 1) or 3-by-3-by-N, R(i,j) = A_ij. Any full real
%   double array is accepted, ranges (0:30:60) included; sparse, single, integer and
%   logical angles are refused.
%   Errors (the message names the argument): cncrot:badFlag, cncrot:badSequence,
%   cncrot:notFinite, cncrot:badSize, cncrot:badClass, cncrot:complex, ... (in a batch, an
%   error in one row names the row).
%
%   Example (the paper's Example 2):
%     R = cncrot_matrix('extrinsic', 'XYZ', [30 45 60])   % R(1,1) = 0.3536
%     R = cncrot_matrix(0, 57, [30 45 60])                % the same, bit for bit
%
%   See also CNCROT_ANGLES, CNCROT_CONVERT, CYCLE600, CONTENTS.
