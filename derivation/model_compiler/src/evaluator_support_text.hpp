#pragma once
// The text of lrchain/model_evaluator_support.hpp (without `#pragma once`), embedded at build time:
// a user model's source is compiled at run time with no include path, so it carries the text itself.
namespace lrchain::model_compiler_detail {
extern const char evaluator_support_text[];
}
