% CNCROT_PROGRAM_WRITE  The program line that programs a frame in a controller's language.
%   [line, status] = cncrot_program_write(dialect, form, F)
%   [line, status] = cncrot_program_write(dialect, form, F, decimals)
%   dialect: a name ('sinumerik', 'heidenhain', 'fanuc', 'syntec', 'twincat', 'haas'; any
%   case, char or string) or a code of cncrot_dialects; form (char or string) the command
%   as written: SINUMERIK 'CYCLE800' (_MODE 57), 'CYCLE800 <_MODE>', 'ROT', 'ROT EULER';
%   Heidenhain 'PLANE SPATIAL', 'PLANE EULER', 'PLANE VECTOR', 'PLANE POINTS', 'PLANE
%   PROJECTED'; Fanuc 'G68.2'; Syntec 'G158' (P10157), 'G158 P<p>', 'G68.2'; TwinCAT 'ROT';
%   Haas 'G268' (Q123), 'G268 Q<q>'. decimals: an integer of any numeric class.
%   F is 4-by-4 or 4-by-4-by-N; line is a char row (a cell column for N ~= 1). decimals < 0
%   (the default) writes the shortest numbers that read back exactly, otherwise numbers are
%   rounded to that many decimals (at most 17). status is 0, or 1 where the middle angle is
%   singular (the free angle sits where that dialect's rule puts it). A frame with an
%   origin for a form without origin words (the PLANE forms, ROT) raises cncrot:hasOrigin:
%   write the datum shift first, then the rotation alone.
%   cncrot_program_lines reads the line back as the same frame.
%
%   Example (a measured plane as a Heidenhain and a Fanuc line):
%     F = cncrot_program_lines('sinumerik', 'CYCLE800(0,"",0,57,10,0,0,30,45,60,0,0,0,-1)');
%     cncrot_program_write('fanuc', 'G68.2', F, 4)
%     cncrot_program_write(cncrot_dialects().FANUC, 'G68.2', F, 4)   % the same
%
%   See also CNCROT_PROGRAM_LINES, CNCROT_PROGRAM_TRANSLATE, CNCROT_DIALECTS, CNCROT_FORM_VALUES.
