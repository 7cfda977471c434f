% CNCROT_ANGLES  Angles (degrees) of rotation matrices in a convention.
%   [angles, status] = cncrot_angles(intrinsic, sequence, R)
%   intrinsic, sequence as in CNCROT_MATRIX ('intrinsic'/'extrinsic' or 1/0; 'ZXY' or 39),
%   the sequence with three rotations (no '0').
%   R: 3-by-3 or 3-by-3-by-N (N may be 0; eye(3), permutation matrices and other full real
%   double arrays are accepted, sparse is refused); angles: N-by-3 in rotation order, theta1
%   and theta3 in (-180, 180], theta2 in [-90, 90] (Tait-Bryan) or [0, 180] (proper Euler).
%   status: N-by-1, 0 or 1 (singular middle angle: theta3 = 0, theta1 carries the free
%   rotation).
%   Errors: cncrot:notARotation (not orthonormal within 1e-3, or a reflection; in a batch
%   the message names the matrix), cncrot:incompleteSequence, cncrot:badSequence,
%   cncrot:badFlag, cncrot:notFinite, ...
%
%   Example:
%     a = cncrot_angles('intrinsic', 'ZXY', cncrot_matrix('extrinsic', 'XYZ', [30 45 60]))
%     % 37.7923 20.7048 49.1066, as cncrot_angles(1, 39, cncrot_matrix(0, 57, [30 45 60]))
%
%   See also CNCROT_MATRIX, CNCROT_CONVERT.
