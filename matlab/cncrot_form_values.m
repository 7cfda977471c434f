% CNCROT_FORM_VALUES  The words of a controller's tilted-plane command for given frames.
%   [words, status] = cncrot_form_values(form, selector, F)
%   The inverse of cncrot_form_frame (form by name, 'plane_spatial', or code, as there): F
%   is 4-by-4 or 4-by-4-by-N; words is N-by-count in the order cncrot_forms lists; status is
%   0, or 1 where the middle angle is singular (the free angle where that dialect puts it).
%   Forms without origin words (SINUMERIK ROT, PLANE SPATIAL/EULER/VECTOR/POINTS/PROJECTED,
%   TwinCAT ROT) need a frame without translation (else cncrot:hasOrigin); ROTS cannot be
%   written (cncrot:badArgument); a projection mode that cannot express the frame raises
%   cncrot:outOfRange. Errors name the argument (and in a batch the frame).
%
%   Example (a measured plane as PLANE SPATIAL and as G68.2):
%     F = cncrot_form_frame('plane_spatial', 0, [30 45 60]);
%     ijk = cncrot_form_values('g68_2', 0, F)   % X Y Z I J K
%
%   See also CNCROT_FORM_FRAME, CNCROT_FORMS, CNCROT_PROGRAM_WRITE.
