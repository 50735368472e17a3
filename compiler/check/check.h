/* check.h — the second stage, the syntax tree checked into the Model (model/model.h). */
#ifndef SPHC_CHECK_H
#define SPHC_CHECK_H

#include "model/model.h"

/* Check the program; returns 0 and fills *m when there are no errors. */
int check_program(const Program *p, Model *m);

#endif
