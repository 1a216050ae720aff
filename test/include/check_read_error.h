// CHECK_READ_ERROR(call, part): `call` throws the program's Read_error, whose
// message contains `part`.

#ifndef ES_TEST_CHECK_READ_ERROR_H
#define ES_TEST_CHECK_READ_ERROR_H

#include <catch2/catch.hpp>

#define CHECK_READ_ERROR(call, part)                                                                         \
  do                                                                                                         \
  {                                                                                                          \
    CHECK_THROWS_AS(call, entropy_simplify::Read_error);                                                     \
    CHECK_THROWS_WITH(call, Catch::Matchers::Contains(part));                                                \
  } while (false)

#endif // ES_TEST_CHECK_READ_ERROR_H
