/* Compiled as C99 and as C++ with -Wall -Wextra -Werror -pedantic: the header alone. */
#include "cncrot.h"
int cncrot_header_check(void);
int cncrot_header_check(void) { return (int)CNCROT_STATUS_OK; }
