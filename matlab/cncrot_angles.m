% CNCROT_ANGLES  Angles (degrees) of rotation matrices in a convention.
%   [angles, status] = cncrot_angles(intrinsic, sequence, R)
%   R: 3-by-3 or 3-by-3-by-N (N may be 0; eye(3), permutation matrices and other full real
%   double arrays are accepted, sparse is refused); angles: N-by-3 in rotation order, theta1 and theta3 in
%   (-180, 180], theta2 in [-90, 90] (Tait-Bryan) or [0, 180] (proper Euler). status: N-by-1,
%   0 or 1 (singular middle angle: theta3 = 0, theta1 carries the free rotation).
%   Errors: cncrot:notARotation (not orthonormal within 1e-3, or a reflection),
%   cncrot:incompleteSequence, cncrot:badSequence, cncrot:badFlag, cncrot:notFinite, ...
%
%   Example: a = cncrot_angles(1, 39, cncrot_matrix(0, 57, [30 45 60]))  % 37.7923 20.7048 49.1066
