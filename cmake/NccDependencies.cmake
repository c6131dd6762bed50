# Finds every third-party dependency; all come from Debian packages (scripts/install-deps.sh).
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(absl REQUIRED)
find_package(CLI11 REQUIRED)
find_package(tomlplusplus REQUIRED)

# ANTLR4: the Debian runtime ships headers and a shared library but no CMake package.
find_path(ANTLR4_INCLUDE_DIR antlr4-runtime.h PATH_SUFFIXES antlr4-runtime REQUIRED)
find_library(ANTLR4_RUNTIME_LIB antlr4-runtime REQUIRED)
find_program(ANTLR4_TOOL antlr4 REQUIRED)
add_library(antlr4_runtime INTERFACE)
target_include_directories(antlr4_runtime SYSTEM INTERFACE ${ANTLR4_INCLUDE_DIR})
target_link_libraries(antlr4_runtime INTERFACE ${ANTLR4_RUNTIME_LIB})

# Generates C++ sources from a grammar at build time.
# Debian's antlr4 tool (4.7.2) writes u8"" literals into std::string initialisers, which
# C++20 types as char8_t; -fno-char8_t restores the C++17 meaning for the generated files only.
function(ncc_antlr_generate out_var grammar_file namespace)
  get_filename_component(name ${grammar_file} NAME_WE)
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(outputs ${out_dir}/${name}Lexer.cpp ${out_dir}/${name}Parser.cpp
              ${out_dir}/${name}Visitor.cpp ${out_dir}/${name}BaseVisitor.cpp)
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${ANTLR4_TOOL} -Dlanguage=Cpp -no-listener -visitor -package ${namespace}
            -o ${out_dir} -Xexact-output-dir ${grammar_file}
    DEPENDS ${grammar_file}
    COMMENT "ANTLR4: generating parser from ${name}.g4"
    VERBATIM)
  set_source_files_properties(${outputs} PROPERTIES GENERATED TRUE
    COMPILE_OPTIONS "-fno-char8_t;-w")
  set(${out_var} ${outputs} PARENT_SCOPE)
  set(${out_var}_DIR ${out_dir} PARENT_SCOPE)
endfunction()
