/* sph_cuda_contact.h — contact between bodies on the device, for the CUDA target: what the
 * model.cu of a scene with contact includes after sph_cuda.h (the code is cuda/contact.h). */
#ifndef SPH_CUDA_CONTACT_H
#define SPH_CUDA_CONTACT_H

#include "cuda/contact.h"

#endif
