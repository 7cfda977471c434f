% CNCROT_CONVERT  Converts angles (degrees) from one convention to another.
%   [angles_out, status] = cncrot_convert(intrinsic_in, sequence_in, angles_in, intrinsic_out, sequence_out)
%   Conventions as in CNCROT_MATRIX: 'intrinsic' or 'extrinsic' (or 1 or 0), and the axis
%   sequence as letters ('XYZ', 'ZXY', "ZX'Y''", 'X0Z') or its code (57, 39, 39, 49), char
%   or string, any case; codes of any numeric class or logical. sequence_in may skip
%   rotations ('0'); sequence_out must have three. angles_in, angles_out: N-by-3 (N may be
%   0). status as in CNCROT_ANGLES. Angles of any size are reduced exactly (1e300 degrees is
%   the rotation of 1e300 mod 360).
%   Errors name the argument, e.g. "cncrot_convert: argument 2 (sequence_in) must be an axis
%   sequence such as 'ZXY' or a code 0..63; got 'ZQY'" (cncrot:badSequence).
%
%   Example (the paper's Example 3, probe angles to CYCLE800 angles):
%     cncrot_convert('extrinsic', 'XYZ', [30 45 60], 'intrinsic', 'ZXY')   % 37.7923 20.7048 49.1066
%     cncrot_convert(0, 57, [30 45 60], 1, 39)                             % the same, bit for bit
%
%   See also CNCROT_MATRIX, CNCROT_ANGLES, CYCLE600.
