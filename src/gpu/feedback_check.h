// A guard against rendering feedback loops (OpenGL 4.5 §9.3.1): a draw whose program can sample
// a texture level that is also an attachment of the bound draw framebuffer has undefined
// results, even with writes to that attachment masked off. Drivers rarely complain (llvmpipe
// renders what it happens to read), so the guard looks for itself: before each draw, when
// enabled, checkFeedback() compares the texture levels the current program's active samplers can
// read with the draw framebuffer's attachments, and throws RuntimeError naming the sampler and the
// attachment on a match.
//
// It is off by default (one state query per sampler and attachment a draw);
// MIRAGE_GL_CHECK_FEEDBACK=1 or setFeedbackChecks(true) turns it on, and debug builds have it on.
// It compares texture names: two views of one storage (Texture::view) are not seen as the same
// texture.
#pragma once

namespace mirage::gpu {

bool feedbackChecks();
void setFeedbackChecks(bool on);

// Throws RuntimeError when the current program and draw framebuffer form a feedback loop; a no-op
// when the checks are off. Call it just before a draw.
void checkFeedback();

}  // namespace mirage::gpu
