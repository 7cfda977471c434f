% CNCROT_CONVERT  Converts angles (degrees) from one convention to another.
%   [angles_out, status] = cncrot_convert(intrinsic_in, sequence_in, angles_in, intrinsic_out, sequence_out)
%   angles_in, angles_out: N-by-3 (N may be 0). Conventions as in cncrot_matrix;
%   sequence_out must have three rotations. status as in cncrot_angles. Angles of any size
%   are reduced exactly (1e300 degrees is the rotation of 1e300 mod 360).
%
%   Example (the paper's Example 3, probe angles to CYCLE800 angles):
%     cncrot_convert(0, 57, [30 45 60], 1, 39)   % 37.7923 20.7048 49.1066
