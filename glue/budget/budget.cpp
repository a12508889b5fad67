// ============================================================================
// tiershade -- glue/budget/budget.cpp
// DX9-like instruction-slot counter for GLSL fragment shaders.
//
//   GLSL 3.30 --glslangValidator -V -R--> SPIR-V --spirv-opt -O--> SPIR-V
//             --spirv-dis--> text --parse + weight table--> BudgetCounts
//
// The counting model (see docs/budget_model.md for the full discussion):
//  * DX9 pixel shaders are vec4 SIMD: a vector instruction up to 4 wide costs
//    one slot.  Instructions that DX9 only has in scalar form (rcp, rsq, exp,
//    log, pow, sincos) are paid once per result component.
//  * Swizzles, component selects, vector construction, loads and stores are
//    free (write masks and source swizzles), negation is a free source
//    modifier, clamp(x,0,1) of a single-use ALU result is a free _sat.
//  * A multiply whose only use is an add/sub in the same block is fused into
//    that add (mad); spirv-opt already turns some mul+add pairs into Fma.
//  * ps_2_x has no flow control: both sides of an if are counted and each phi
//    at a merge costs one cmp; loops that survive spirv-opt are unrolled by
//    simulating their constant trip count, otherwise it is an error.
//  * ps_2_x writes oC#/oDepth only with mov: one slot per output written.
//  * texld* and texkill are texture slots; everything else is arithmetic.
//
// Layout of this file:
//   1. subprocess and temp-dir helpers
//   2. source preparation (#version handling)
//   3. SPIR-V disassembly parser
//   4. the weight table (data; also printed as markdown)
//   5. the counter (fusion analysis, loops, per-instruction costs)
//   6. public API
//   7. Mesa NIR (ST_DEBUG=nir) cross-check counter
// ============================================================================
#include "budget/budget.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace {

// ----------------------------------------------------------------------------
// 1. Subprocess and temp-dir helpers
// ----------------------------------------------------------------------------

// A private directory from mkdtemp, removed with its contents on destruction.
class TempDir {
public:
    TempDir() {
        const char *base = std::getenv("TMPDIR");
        std::string tmpl = std::string(base && *base ? base : "/tmp") + "/tiershade-budget-XXXXXX";
        std::vector<char> buf(tmpl.begin(), tmpl.end());
        buf.push_back('\0');
        if (mkdtemp(buf.data()) != nullptr) path_ = buf.data();
        else error_ = std::string("mkdtemp(") + tmpl + ") failed: " + std::strerror(errno);
    }
    ~TempDir() {
        if (!path_.empty()) {
            std::error_code ec;
            std::filesystem::remove_all(path_, ec);
        }
    }
    TempDir(const TempDir &) = delete;
    TempDir &operator=(const TempDir &) = delete;

    bool ok() const { return !path_.empty(); }
    const std::string &error() const { return error_; }
    std::string file(const std::string &name) const { return path_ + "/" + name; }
    const std::string &path() const { return path_; }

private:
    std::string path_;
    std::string error_;
};

bool write_file(const std::string &path, const std::string &text, std::string *err) {
    std::ofstream f(path, std::ios::binary);
    if (!f) { *err = "cannot create " + path; return false; }
    f << text;
    f.close();
    if (!f) { *err = "cannot write " + path; return false; }
    return true;
}

std::string read_file(const std::string &path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return std::string();
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// Runs argv[0] (looked up in PATH) with stdin from /dev/null and stdout and
// stderr redirected to files.  Returns false if it could not be started or
// did not exit normally; *exit_code gets the exit status otherwise.
bool run_tool(const std::vector<std::string> &argv, const std::string &out_path,
              const std::string &err_path, int *exit_code, std::string *err) {
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0) { *err = "posix_spawn_file_actions_init failed"; return false; }
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_addopen(&fa, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);

    std::vector<char *> args;
    for (const std::string &a : argv) args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);

    pid_t pid = 0;
    int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        *err = "cannot run " + argv[0] + ": " + std::strerror(rc) + " (is it installed and in PATH?)";
        return false;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) { *err = "waitpid failed for " + argv[0] + ": " + std::strerror(errno); return false; }
    }
    if (WIFSIGNALED(status)) {
        *err = argv[0] + " was killed by signal " + std::to_string(WTERMSIG(status));
        return false;
    }
    *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return true;
}

std::string trim(const std::string &s) {
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return std::string();
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

// Makes a tool log readable: removes our temp directory from paths, the bare
// file-name line glslang echoes, and blank lines.
std::string clean_log(const std::string &text, const std::string &dir, const std::string &echoed_name) {
    const std::string needle = dir + "/";
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
        for (size_t p; (p = line.find(needle)) != std::string::npos;) line.erase(p, needle.size());
        line = trim(line);
        if (line.empty() || line == echoed_name) continue;
        out += line + "\n";
    }
    return out.empty() ? std::string("(no output)\n") : out;
}

// ----------------------------------------------------------------------------
// 2. Source preparation
// ----------------------------------------------------------------------------
// glslang -V wants desktop GLSL >= 330 (or ES >= 310).  We keep the line count
// unchanged so compile errors point at the caller's lines.
bool prepare_source(const std::string &src, std::string *out, std::string *err) {
    std::istringstream in(src);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);

    for (size_t i = 0; i < lines.size(); ++i) {
        std::string t = trim(lines[i]);
        if (t.empty() || t.rfind("//", 0) == 0) continue;  // blank or comment lines may precede #version
        if (t[0] == '#') {
            std::string rest = trim(t.substr(1));
            if (rest.rfind("version", 0) == 0) {
                std::istringstream vs(rest.substr(7));
                int version = 0;
                std::string profile;
                vs >> version >> profile;
                if (version <= 0) { *err = "malformed #version line: " + t; return false; }
                if (profile == "es") {
                    *err = "ES shaders are not accepted; pass GLSL 3.30 core (got: " + t + ")";
                    return false;
                }
                lines[i] = "#version " + std::to_string(version < 330 ? 330 : version) + " core";
                std::string joined;
                for (const std::string &l : lines) joined += l + "\n";
                *out = joined;
                return true;
            }
        }
        break;  // first real line is not #version
    }
    // No version line: GLSL would assume 110; we assume the caller meant 330.
    // "#line 1" (3.30 semantics: the next line is line 1) keeps line numbers.
    *out = "#version 330 core\n#line 1\n" + src;
    return true;
}

// ----------------------------------------------------------------------------
// 3. SPIR-V disassembly parser
// ----------------------------------------------------------------------------
struct Inst {
    std::string result;             // "%id" or empty
    std::string type;               // result type id or empty
    std::string op;                 // "OpFAdd", ...
    std::vector<std::string> args;  // operands after the result type
};

struct Block {
    std::string label;
    std::vector<Inst> insts;
    std::vector<std::string> succ;
    std::string merge;     // from OpSelectionMerge / OpLoopMerge
    std::string cont;      // continue target (loop headers only)
    bool loop_header = false;
};

struct Function {
    std::string id;
    std::vector<Block> blocks;
};

struct TypeInfo {
    enum Kind { Scalar, Vector, Matrix, Other } kind = Other;
    int comps = 1;  // vector width, or rows for a matrix
    int cols = 1;   // matrix columns
};

struct ConstInfo {
    std::string type;            // type id
    bool known = false;          // numeric values available
    std::vector<double> values;  // flattened components
};

struct Module {
    std::map<std::string, TypeInfo> types;
    std::map<std::string, ConstInfo> consts;         // OpConstant*, OpSpecConstant*, OpUndef
    std::map<std::string, std::string> var_storage;  // OpVariable id -> storage class
    std::map<std::string, std::string> ext_sets;     // OpExtInstImport id -> set name
    std::vector<Function> functions;
    std::string fragment_entry;
};

std::vector<std::string> tokenize(const std::string &line) {
    std::vector<std::string> toks;
    size_t i = 0, n = line.size();
    while (i < n) {
        while (i < n && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= n) break;
        if (line[i] == ';') break;  // comment
        std::string tok;
        if (line[i] == '"') {
            tok += line[i++];
            while (i < n && line[i] != '"') {
                if (line[i] == '\\' && i + 1 < n) tok += line[i++];
                tok += line[i++];
            }
            if (i < n) tok += line[i++];
        } else {
            while (i < n && !std::isspace(static_cast<unsigned char>(line[i]))) tok += line[i++];
        }
        toks.push_back(tok);
    }
    return toks;
}

bool is_id(const std::string &t) { return !t.empty() && t[0] == '%'; }

bool has_result_type(const std::string &op) {
    if (op.rfind("OpType", 0) == 0) return false;
    return op != "OpLabel" && op != "OpExtInstImport" && op != "OpString" && op != "OpDecorationGroup";
}

int type_size(const Module &m, const std::string &type) {
    auto it = m.types.find(type);
    if (it == m.types.end()) return 1;
    return it->second.comps * it->second.cols;
}

bool parse_disassembly(const std::string &text, Module *m, std::string *err) {
    std::istringstream in(text);
    std::string line;
    Function *fn = nullptr;
    Block *blk = nullptr;
    int lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        std::vector<std::string> t = tokenize(line);
        if (t.empty()) continue;
        Inst inst;
        size_t k = 0;
        if (t.size() >= 3 && t[1] == "=") { inst.result = t[0]; k = 2; }
        inst.op = t[k++];
        if (!inst.result.empty() && has_result_type(inst.op) && k < t.size()) inst.type = t[k++];
        inst.args.assign(t.begin() + static_cast<long>(k), t.end());
        const std::string &op = inst.op;
        const std::vector<std::string> &a = inst.args;

        if (op == "OpFunction") {
            m->functions.push_back(Function());
            fn = &m->functions.back();
            fn->id = inst.result;
            blk = nullptr;
            continue;
        }
        if (op == "OpFunctionEnd") { fn = nullptr; blk = nullptr; continue; }
        if (fn) {
            if (op == "OpLabel") {
                fn->blocks.push_back(Block());
                blk = &fn->blocks.back();
                blk->label = inst.result;
                continue;
            }
            if (!blk) {
                if (op == "OpFunctionParameter") continue;
                *err = "spirv-dis line " + std::to_string(lineno) + ": instruction outside a block: " + line;
                return false;
            }
            if (op == "OpBranch" && a.size() >= 1) blk->succ.push_back(a[0]);
            if (op == "OpBranchConditional" && a.size() >= 3) { blk->succ.push_back(a[1]); blk->succ.push_back(a[2]); }
            if (op == "OpSwitch" && a.size() >= 2) {
                blk->succ.push_back(a[1]);
                for (size_t i = 3; i < a.size(); i += 2) blk->succ.push_back(a[i]);
            }
            if (op == "OpSelectionMerge" && !a.empty()) blk->merge = a[0];
            if (op == "OpLoopMerge" && a.size() >= 2) { blk->merge = a[0]; blk->cont = a[1]; blk->loop_header = true; }
            if (op == "OpUndef") { ConstInfo c; c.type = inst.type; m->consts[inst.result] = c; }
            blk->insts.push_back(inst);
            continue;
        }

        // Module-level declarations.
        if (op == "OpEntryPoint" && a.size() >= 2 && a[0] == "Fragment" && m->fragment_entry.empty())
            m->fragment_entry = a[1];
        else if (op == "OpExtInstImport" && !a.empty()) {
            std::string name = a[0];
            if (name.size() >= 2 && name.front() == '"') name = name.substr(1, name.size() - 2);
            m->ext_sets[inst.result] = name;
        } else if (op == "OpTypeFloat" || op == "OpTypeInt" || op == "OpTypeBool") {
            TypeInfo ti; ti.kind = TypeInfo::Scalar; m->types[inst.result] = ti;
        } else if (op == "OpTypeVector" && a.size() >= 2) {
            TypeInfo ti; ti.kind = TypeInfo::Vector; ti.comps = std::atoi(a[1].c_str()); m->types[inst.result] = ti;
        } else if (op == "OpTypeMatrix" && a.size() >= 2) {
            TypeInfo ti; ti.kind = TypeInfo::Matrix; ti.cols = std::atoi(a[1].c_str());
            auto col = m->types.find(a[0]);
            ti.comps = col != m->types.end() ? col->second.comps : 4;
            m->types[inst.result] = ti;
        } else if (op.rfind("OpType", 0) == 0) {
            m->types[inst.result] = TypeInfo();
        } else if (op == "OpConstant" || op == "OpSpecConstant") {
            ConstInfo c;
            if (!a.empty()) {
                char *end = nullptr;
                double v = std::strtod(a[0].c_str(), &end);
                if (end && *end == '\0') { c.known = true; c.values.push_back(v); }
            }
            m->consts[inst.result] = c;
        } else if (op == "OpConstantTrue" || op == "OpSpecConstantTrue" || op == "OpConstantFalse" ||
                   op == "OpSpecConstantFalse") {
            ConstInfo c; c.known = true; c.values.push_back(op.find("True") != std::string::npos ? 1.0 : 0.0);
            m->consts[inst.result] = c;
        } else if (op == "OpConstantComposite" || op == "OpSpecConstantComposite") {
            ConstInfo c; c.known = true;
            for (const std::string &id : a) {
                auto it = m->consts.find(id);
                if (it == m->consts.end() || !it->second.known) { c.known = false; c.values.clear(); break; }
                c.values.insert(c.values.end(), it->second.values.begin(), it->second.values.end());
            }
            m->consts[inst.result] = c;
        } else if (op == "OpConstantNull") {
            ConstInfo c; c.known = true; c.values.assign(static_cast<size_t>(type_size(*m, inst.type)), 0.0);
            m->consts[inst.result] = c;
        } else if (op.rfind("OpConstant", 0) == 0 || op.rfind("OpSpecConstant", 0) == 0 || op == "OpUndef") {
            m->consts[inst.result] = ConstInfo();  // a constant without usable numeric value
        } else if (op == "OpVariable" && !a.empty()) {
            m->var_storage[inst.result] = a[0];
        }
        auto c = m->consts.find(inst.result);
        if (c != m->consts.end()) c->second.type = inst.type;
    }
    if (m->fragment_entry.empty()) { *err = "no Fragment entry point in the SPIR-V"; return false; }
    return true;
}

// ----------------------------------------------------------------------------
// 4. The weight table
// ----------------------------------------------------------------------------
// Each row covers one or more SPIR-V opcodes (ext = false) or GLSL.std.450
// extended instructions (ext = true), separated by spaces.  Rows with a
// `special` text have their cost computed by a dedicated rule in section 5;
// the others cost `fixed + per_comp * result components` slots of `unit`.
enum class Unit { Free, Alu, Tex };

struct Rule {
    const char *ops;
    bool ext;
    Unit unit;
    int fixed;
    int per_comp;
    const char *dx9;
    const char *special;  // nullptr: plain fixed/per-component cost
};

const Rule kRules[] = {
    // --- free: register access, swizzles, modifiers --------------------------------------------
    {"OpLoad OpAccessChain OpInBoundsAccessChain OpCompositeExtract OpCopyObject OpCopyLogical "
     "OpVariable OpUndef OpSampledImage OpImage OpFunctionParameter",
     false, Unit::Free, 0, 0, "register / constant access, source swizzle", nullptr},
    {"OpVectorShuffle OpCompositeConstruct OpCompositeInsert", false, Unit::Alu, 0, 0,
     "write masks and swizzles; `mov r.w, c` for constant lanes",
     "0; 1 when it mixes constant lanes with computed lanes (e.g. `vec4(rgb, 1.0)`)"},
    {"OpStore", false, Unit::Alu, 0, 0, "`mov oC#` / `mov oDepth` (+ `cmp`)",
     "0; 1 per distinct Output variable written (ps_2_x writes oC#/oDepth only with mov, once), "
     "+1 `cmp` per extra block that stores the same output (flattened early returns)"},
    {"OpFNegate OpSNegate", false, Unit::Free, 0, 0, "`-r` source modifier", nullptr},
    {"OpLogicalNot", false, Unit::Free, 0, 0, "swap the `cmp` operands", nullptr},
    {"OpBitcast OpConvertSToF OpConvertUToF OpFConvert OpSConvert OpUConvert", false, Unit::Free, 0, 0,
     "none: DX9 registers are float, integers are floats", nullptr},
    {"OpTranspose", false, Unit::Free, 0, 0, "none: `dp4` rows instead of `mul`/`mad` columns", nullptr},
    {"OpImageQuerySize OpImageQuerySizeLod OpImageQueryLevels OpImageQuerySamples", false, Unit::Free, 0, 0,
     "a constant set by the application", nullptr},
    {"OpLabel OpBranch OpBranchConditional OpSelectionMerge OpLoopMerge OpReturn OpReturnValue "
     "OpUnreachable OpLine OpNoLine OpNop",
     false, Unit::Free, 0, 0, "none: ps_2_x has no flow control",
     "0; every block of an if/switch is counted (flattened), loops are unrolled (trip count x body)"},
    // --- arithmetic ------------------------------------------------------------------------------
    {"OpSwitch", false, Unit::Alu, 0, 0, "`add` forming selector - case for each `cmp`",
     "1 per case label other than 0; 0 with a constant selector"},
    {"OpFAdd OpFSub", false, Unit::Alu, 1, 0, "`add`", nullptr},
    {"OpFMul OpVectorTimesScalar", false, Unit::Alu, 1, 0, "`mul`, or the mul half of `mad`",
     "1; 0 when its only use is an OpFAdd/OpFSub in the same block (fused into `mad`; an add absorbs one mul)"},
    {"OpDot", false, Unit::Alu, 1, 0, "`dp3` / `dp4` / `dp2add`",
     "1; 2 for vec2 (`dp2add` is a 2-slot ps_2_0 macro), and a single-use OpFAdd/OpFSub of that result is then free"},
    {"OpFDiv", false, Unit::Alu, 0, 0, "`rcp` (scalar) + `mul`",
     "1 `rcp` per divisor component (1 if the divisor is a scalar splat) + 1 `mul`; 0 rcp if the divisor is "
     "constant; no mul if the dividend is the constant 1"},
    {"OpFMod OpFRem", false, Unit::Alu, 0, 0, "division + `frc` + `mul`", "OpFDiv cost + 2"},
    {"OpSelect", false, Unit::Alu, 1, 0, "`cmp`", nullptr},
    {"OpPhi", false, Unit::Alu, 0, 0, "`cmp` merging a flattened if/switch",
     "k-1 for k incoming values; 0 in a loop header (register reuse once unrolled)"},
    {"OpFOrdEqual OpFUnordEqual OpFOrdNotEqual OpFUnordNotEqual OpFOrdLessThan OpFUnordLessThan "
     "OpFOrdGreaterThan OpFUnordGreaterThan OpFOrdLessThanEqual OpFUnordLessThanEqual "
     "OpFOrdGreaterThanEqual OpFUnordGreaterThanEqual",
     false, Unit::Alu, 0, 0, "`add` forming a-b for `cmp` / `texkill`",
     "0 when one operand is the constant 0 (cmp/texkill test the value itself); 1 otherwise"},
    {"OpLogicalAnd OpLogicalOr OpLogicalEqual OpLogicalNotEqual", false, Unit::Alu, 1, 0,
     "`mul` / `add` / `cmp` on 0-1 masks", nullptr},
    {"OpAny OpAll", false, Unit::Alu, 2, 0, "`dp4` + `cmp`", nullptr},
    {"OpIsNan OpIsInf", false, Unit::Alu, 1, 0, "none in DX9 (harness only)", nullptr},
    {"OpIAdd OpISub OpIMul OpSDiv OpUDiv OpSMod OpSRem OpUMod OpShiftLeftLogical OpShiftRightLogical "
     "OpShiftRightArithmetic OpBitwiseAnd OpBitwiseOr OpBitwiseXor OpNot OpIEqual OpINotEqual OpSLessThan "
     "OpSLessThanEqual OpSGreaterThan OpSGreaterThanEqual OpULessThan OpULessThanEqual OpUGreaterThan "
     "OpUGreaterThanEqual",
     false, Unit::Alu, 1, 0, "none: DX9 has no integer ALU (harness code only)", nullptr},
    {"OpConvertFToS OpConvertFToU", false, Unit::Alu, 2, 0, "`frc` + `add` (floor; exact for x >= 0)", nullptr},
    {"OpMatrixTimesVector OpVectorTimesMatrix", false, Unit::Alu, 0, 0, "`m4x4`, `m3x3`, ... (one `dp` per row)",
     "1 per result component (mat4*vec4 = 4, mat3*vec3 = 3)"},
    {"OpMatrixTimesMatrix", false, Unit::Alu, 0, 0, "one `mNxM` per result column", "result columns x result rows"},
    {"OpMatrixTimesScalar OpOuterProduct", false, Unit::Alu, 0, 0, "`mul` per column", "1 per result column"},
    {"OpDPdx OpDPdy OpDPdxFine OpDPdyFine OpDPdxCoarse OpDPdyCoarse", false, Unit::Alu, 1, 0,
     "`dsx` / `dsy` (ps_2_x only; not in ps_2_0)", nullptr},
    {"OpFwidth OpFwidthFine OpFwidthCoarse", false, Unit::Alu, 5, 0, "`dsx`, `dsy`, `abs`, `abs`, `add`", nullptr},
    // --- texture -------------------------------------------------------------------------------
    {"OpImageSampleImplicitLod OpImageSampleExplicitLod OpImageSampleDrefImplicitLod "
     "OpImageSampleDrefExplicitLod OpImageSampleProjImplicitLod OpImageSampleProjExplicitLod "
     "OpImageSampleProjDrefImplicitLod OpImageSampleProjDrefExplicitLod OpImageFetch OpImageGather "
     "OpImageDrefGather",
     false, Unit::Tex, 1, 0, "`texld` / `texldp` / `texldb` (`texldl` in ps_3_0)", nullptr},
    {"OpKill OpTerminateInvocation OpDemoteToHelperInvocation", false, Unit::Tex, 1, 0,
     "`texkill` (a texture instruction in ps_2_0)", nullptr},
    {"OpFunctionCall", false, Unit::Free, 0, 0, "none", "error: spirv-opt -O inlines every call"},
    // --- GLSL.std.450 extended instructions -----------------------------------------------------
    {"Fma", true, Unit::Alu, 1, 0, "`mad`", nullptr},
    {"FMin FMax UMin UMax SMin SMax NMin NMax", true, Unit::Alu, 1, 0, "`min` / `max`", nullptr},
    {"FClamp NClamp", true, Unit::Alu, 0, 0, "`_sat` modifier, `mov_sat`, or `max` + `min`",
     "clamp(x,0,1): 0 if x is a single-use ALU result in the same block, or a vector built only from such "
     "results (`_sat`), else 1 (`mov_sat`); other bounds: 2"},
    {"UClamp SClamp", true, Unit::Alu, 2, 0, "`max` + `min`", nullptr},
    {"FMix", true, Unit::Alu, 2, 0, "`lrp` (2-slot macro)", nullptr},
    {"Step", true, Unit::Alu, 0, 0, "`cmp` (+ `add`)", "1 with a constant 0 edge, else 2"},
    {"SmoothStep", true, Unit::Alu, 0, 0, "`mad_sat`, `mad`, `mul`, `mul` (+ `add`, `add`, `rcp`)",
     "4 with constant edges, else 7"},
    {"FAbs SAbs", true, Unit::Alu, 1, 0, "`abs` (the `_abs` source modifier is ps_3_0 only)", nullptr},
    {"FSign SSign", true, Unit::Alu, 2, 0, "`cmp`, `cmp`", nullptr},
    {"Fract", true, Unit::Alu, 1, 0, "`frc`", nullptr},
    {"Floor Ceil Modf ModfStruct", true, Unit::Alu, 2, 0, "`frc` + `add`", nullptr},
    {"Round RoundEven", true, Unit::Alu, 3, 0, "`add`, `frc`, `add`", nullptr},
    {"Trunc", true, Unit::Alu, 4, 0, "`frc`, `add`, `cmp`, `add`", nullptr},
    {"Radians Degrees", true, Unit::Alu, 1, 0, "`mul`", nullptr},
    {"Exp2 Log2", true, Unit::Alu, 0, 1, "`exp` / `log` (scalar)", nullptr},
    {"Exp Log", true, Unit::Alu, 1, 1, "`mul` + scalar `exp` / `log`", nullptr},
    {"Pow", true, Unit::Alu, 0, 3, "`pow` (scalar 3-slot macro: log, mul, exp)", nullptr},
    {"InverseSqrt", true, Unit::Alu, 0, 1, "`rsq` (scalar)", nullptr},
    {"Sqrt", true, Unit::Alu, 0, 2, "`rsq` + `rcp` (scalar)", nullptr},
    {"Sin Cos", true, Unit::Alu, 0, 8, "`sincos` (scalar 8-slot macro)", nullptr},
    {"Tan", true, Unit::Alu, 0, 10, "`sincos` + `rcp` + `mul`", nullptr},
    {"Asin Acos", true, Unit::Alu, 0, 10, "polynomial + sqrt (rough)", nullptr},
    {"Atan", true, Unit::Alu, 0, 12, "rcp + polynomial + cmp (rough)", nullptr},
    {"Atan2", true, Unit::Alu, 0, 16, "as atan plus quadrant fix-up (rough)", nullptr},
    {"Sinh Cosh", true, Unit::Alu, 0, 4, "`exp`, `rcp`, `add`, `mul` (rough)", nullptr},
    {"Tanh", true, Unit::Alu, 0, 5, "`exp`, `add`, `rcp`, `mad` (rough)", nullptr},
    {"Asinh Acosh Atanh", true, Unit::Alu, 0, 6, "`log` + sqrt or rcp (rough)", nullptr},
    {"Length", true, Unit::Alu, 0, 0, "`dp3`, `rsq`, `rcp`", "3; 1 (`abs`) for a scalar"},
    {"Distance", true, Unit::Alu, 0, 0, "`add` + `dp3`, `rsq`, `rcp`", "4; 2 for scalars"},
    {"Normalize", true, Unit::Alu, 3, 0, "`nrm` (3-slot macro: dp3, rsq, mul)", nullptr},
    {"Cross", true, Unit::Alu, 2, 0, "`crs` (2-slot macro)", nullptr},
    {"FaceForward", true, Unit::Alu, 2, 0, "`dp3` + `cmp`", nullptr},
    {"Reflect", true, Unit::Alu, 3, 0, "`dp3`, `add`, `mad`", nullptr},
    {"Refract", true, Unit::Alu, 8, 0, "dp3, mad, mad, rsq, rcp, mad, mad, cmp (rough)", nullptr},
    {"Determinant", true, Unit::Alu, 0, 0, "`mul`/`mad` chains", "2 (2x2), 3 (3x3: crs + dp3), 12 (4x4, rough)"},
    {"MatrixInverse", true, Unit::Alu, 0, 0, "cofactors + rcp (rough)", "4 (2x2), 12 (3x3), 36 (4x4)"},
};

std::string rule_slots_text(const Rule &r) {
    if (r.special) return r.special;
    if (r.unit == Unit::Free) return "0";
    std::string u = r.unit == Unit::Tex ? " tex" : "";
    if (r.per_comp == 0) return std::to_string(r.fixed) + u;
    std::string pc = std::to_string(r.per_comp) + " per result component";
    if (r.fixed == 0) return pc + u;
    return std::to_string(r.fixed) + " + " + pc + u;
}

// ----------------------------------------------------------------------------
// 5. The counter
// ----------------------------------------------------------------------------
constexpr int kMaxTrips = 1024;          // per loop
constexpr long kMaxMultiplier = 1 << 20;  // product over nested loops

struct Cost {
    int alu = 0;
    int tex = 0;
    std::string name;
};

class Counter {
public:
    explicit Counter(const Module &m) : m_(m) {
        for (const Rule &r : kRules) {
            std::istringstream ss(r.ops);
            std::string name;
            while (ss >> name) (r.ext ? ext_rules_ : core_rules_)[name] = &r;
        }
    }

    bool count(BudgetCounts *out, std::string *err);

private:
    struct LoopInfo {
        std::string header, merge;
        std::set<std::string> body;      // includes the header
        std::set<std::string> prefix;    // blocks executed before the exit test (top-tested loops)
        long trips_prefix = 0;           // executions of prefix blocks
        long trips_body = 0;             // executions of the other body blocks
    };

    // --- lookups ---
    const Inst *def(const std::string &id) const {
        auto it = defs_.find(id);
        return it == defs_.end() ? nullptr : it->second;
    }
    int uses(const std::string &id) const {
        auto it = use_count_.find(id);
        return it == use_count_.end() ? 0 : it->second;
    }
    const ConstInfo *constant(const std::string &id) const {
        auto it = m_.consts.find(id);
        return it == m_.consts.end() ? nullptr : &it->second;
    }
    bool is_const(const std::string &id) const { return constant(id) != nullptr || derived_.count(id) > 0; }
    bool const_all(const std::string &id, double v) const {
        const ConstInfo *c = constant(id);
        if (!c || !c->known || c->values.empty()) return false;
        for (double x : c->values) if (x != v) return false;
        return true;
    }
    const TypeInfo &type_of(const std::string &type_id) const {
        auto it = m_.types.find(type_id);
        return it == m_.types.end() ? unknown_type_ : it->second;
    }
    int comps(const std::string &type_id) const { return type_of(type_id).comps; }
    // type id of any value: instruction result or constant
    std::string value_type(const std::string &id) const {
        if (const Inst *d = def(id)) return d->type;
        if (const ConstInfo *c = constant(id)) return c->type;
        return std::string();
    }
    // operand ids of an instruction (for OpExtInst without the set and the name)
    std::vector<std::string> id_operands(const Inst &in) const {
        std::vector<std::string> ids;
        size_t start = in.op == "OpExtInst" ? 2 : 0;
        for (size_t i = start; i < in.args.size(); ++i)
            if (is_id(in.args[i])) ids.push_back(in.args[i]);
        return ids;
    }
    std::string ext_name(const Inst &in) const {
        if (in.op != "OpExtInst" || in.args.size() < 2) return std::string();
        auto it = m_.ext_sets.find(in.args[0]);
        if (it == m_.ext_sets.end() || it->second != "GLSL.std.450") return std::string();
        return in.args[1];
    }
    std::string ext_set(const Inst &in) const {
        if (in.op != "OpExtInst" || in.args.empty()) return std::string();
        auto it = m_.ext_sets.find(in.args[0]);
        return it == m_.ext_sets.end() ? std::string() : it->second;
    }
    // operand i of an ext inst (after set and name)
    std::string ext_arg(const Inst &in, size_t i) const {
        return in.args.size() > i + 2 ? in.args[i + 2] : std::string();
    }

    bool analyse_function(const Function &f, std::string *err);
    bool analyse_loop(const Block &header, LoopInfo *loop, std::string *err);
    std::optional<double> eval(const std::string &id, const std::map<std::string, double> &env, int depth) const;
    void analyse_fusion(const Function &f);
    void propagate_derived(const Function &f);
    Cost cost(const Inst &in, const Block &b) const;
    Cost ext_cost(const Inst &in) const;
    int div_cost(const Inst &in) const;
    std::string output_variable(const std::string &ptr) const;

    const Module &m_;
    const TypeInfo unknown_type_;
    std::map<std::string, const Rule *> core_rules_, ext_rules_;
    // per-function analysis state
    std::map<std::string, const Inst *> defs_;
    std::map<std::string, std::string> def_block_;
    std::map<std::string, int> use_count_;
    std::map<std::string, const Block *> blocks_;
    std::set<std::string> reachable_;
    std::vector<LoopInfo> loops_;
    std::set<std::string> induction_;   // loop induction phis and their updates
    std::set<std::string> derived_;     // values that fold to constants once loops are unrolled
    std::set<std::string> fused_mul_;   // muls absorbed into a mad
    std::set<std::string> free_add_;    // adds absorbed into dp2add
    std::set<std::string> sat_clamp_;   // clamp(x,0,1) done as _sat
};

std::string Counter::output_variable(const std::string &ptr) const {
    std::string id = ptr;
    for (int guard = 0; guard < 16; ++guard) {
        auto v = m_.var_storage.find(id);
        if (v != m_.var_storage.end()) return v->second == "Output" ? id : std::string();
        const Inst *d = def(id);
        if (!d || (d->op != "OpAccessChain" && d->op != "OpInBoundsAccessChain") || d->args.empty())
            return std::string();
        id = d->args[0];
    }
    return std::string();
}

// Small evaluator for loop trip counts: constants, the induction values in
// env, and integer/float arithmetic and comparisons on them.
std::optional<double> Counter::eval(const std::string &id, const std::map<std::string, double> &env,
                                    int depth) const {
    if (depth > 64) return std::nullopt;
    auto e = env.find(id);
    if (e != env.end()) return e->second;
    if (const ConstInfo *c = constant(id)) {
        if (c->known && c->values.size() == 1) return c->values[0];
        return std::nullopt;
    }
    const Inst *d = def(id);
    if (!d) return std::nullopt;
    const std::string &op = d->op;
    std::vector<double> v;
    for (const std::string &a : d->args) {
        if (!is_id(a)) return std::nullopt;
        std::optional<double> x = eval(a, env, depth + 1);
        if (!x || !std::isfinite(*x) || std::fabs(*x) > 1e15) return std::nullopt;  // keep int casts defined
        v.push_back(*x);
    }
    auto need = [&](size_t n) { return v.size() == n; };
    auto as_int = [](double x) { return static_cast<long long>(x); };
    if (op == "OpCopyObject" && need(1)) return v[0];
    if ((op == "OpIAdd" || op == "OpFAdd") && need(2)) return v[0] + v[1];
    if ((op == "OpISub" || op == "OpFSub") && need(2)) return v[0] - v[1];
    if ((op == "OpIMul" || op == "OpFMul") && need(2)) return v[0] * v[1];
    if ((op == "OpSDiv" || op == "OpUDiv") && need(2) && as_int(v[1]) != 0)
        return static_cast<double>(as_int(v[0]) / as_int(v[1]));
    if (op == "OpFDiv" && need(2) && v[1] != 0.0) return v[0] / v[1];
    if ((op == "OpSNegate" || op == "OpFNegate") && need(1)) return -v[0];
    const bool shift_ok = need(2) && v[0] >= 0.0 && v[1] >= 0.0 && v[1] < 32.0;
    if (op == "OpShiftLeftLogical" && shift_ok) return static_cast<double>(as_int(v[0]) << as_int(v[1]));
    if ((op == "OpShiftRightArithmetic" || op == "OpShiftRightLogical") && shift_ok)
        return static_cast<double>(as_int(v[0]) >> as_int(v[1]));
    if ((op == "OpConvertSToF" || op == "OpConvertUToF") && need(1)) return v[0];
    if ((op == "OpConvertFToS" || op == "OpConvertFToU") && need(1)) return std::trunc(v[0]);
    if (op == "OpLogicalNot" && need(1)) return v[0] != 0.0 ? 0.0 : 1.0;
    if (op == "OpLogicalAnd" && need(2)) return (v[0] != 0.0 && v[1] != 0.0) ? 1.0 : 0.0;
    if (op == "OpLogicalOr" && need(2)) return (v[0] != 0.0 || v[1] != 0.0) ? 1.0 : 0.0;
    if (op == "OpSelect" && need(3)) return v[0] != 0.0 ? v[1] : v[2];
    if (need(2)) {
        static const char *const lt[] = {"OpSLessThan", "OpULessThan", "OpFOrdLessThan", "OpFUnordLessThan"};
        static const char *const le[] = {"OpSLessThanEqual", "OpULessThanEqual", "OpFOrdLessThanEqual",
                                         "OpFUnordLessThanEqual"};
        static const char *const gt[] = {"OpSGreaterThan", "OpUGreaterThan", "OpFOrdGreaterThan",
                                         "OpFUnordGreaterThan"};
        static const char *const ge[] = {"OpSGreaterThanEqual", "OpUGreaterThanEqual", "OpFOrdGreaterThanEqual",
                                         "OpFUnordGreaterThanEqual"};
        static const char *const eq[] = {"OpIEqual", "OpFOrdEqual", "OpFUnordEqual", "OpLogicalEqual"};
        static const char *const ne[] = {"OpINotEqual", "OpFOrdNotEqual", "OpFUnordNotEqual", "OpLogicalNotEqual"};
        auto in = [&](const char *const *list, size_t n) {
            for (size_t i = 0; i < n; ++i) if (op == list[i]) return true;
            return false;
        };
        if (in(lt, 4)) return v[0] < v[1] ? 1.0 : 0.0;
        if (in(le, 4)) return v[0] <= v[1] ? 1.0 : 0.0;
        if (in(gt, 4)) return v[0] > v[1] ? 1.0 : 0.0;
        if (in(ge, 4)) return v[0] >= v[1] ? 1.0 : 0.0;
        if (in(eq, 4)) return v[0] == v[1] ? 1.0 : 0.0;
        if (in(ne, 4)) return v[0] != v[1] ? 1.0 : 0.0;
    }
    return std::nullopt;
}

// Finds the loop's body, its induction variables and its trip count.
bool Counter::analyse_loop(const Block &header, LoopInfo *loop, std::string *err) {
    loop->header = header.label;
    loop->merge = header.merge;
    const std::string where = "loop at block " + header.label;

    // Body: everything reachable from the header without passing the merge block.
    std::vector<std::string> work{header.label};
    loop->body.insert(header.label);
    while (!work.empty()) {
        std::string b = work.back();
        work.pop_back();
        auto it = blocks_.find(b);
        if (it == blocks_.end()) continue;
        for (const std::string &s : it->second->succ)
            if (s != loop->merge && loop->body.insert(s).second) work.push_back(s);
    }

    // Induction candidates: header phis (value, parent) pairs with a constant
    // value from outside the loop and an update from inside.
    struct Phi { std::string id, init, update; };
    std::vector<Phi> cands;
    for (const Inst &in : header.insts) {
        if (in.op != "OpPhi") continue;
        if (in.args.size() != 4) continue;
        Phi p;
        p.id = in.result;
        for (size_t i = 0; i + 1 < in.args.size(); i += 2) {
            if (loop->body.count(in.args[i + 1])) p.update = in.args[i];
            else p.init = in.args[i];
        }
        const ConstInfo *c = constant(p.init);
        if (p.update.empty() || !c || !c->known || c->values.size() != 1) continue;
        cands.push_back(p);
    }
    std::map<std::string, double> env;
    for (bool changed = true; changed;) {
        changed = false;
        env.clear();
        for (const Phi &p : cands) env[p.id] = constant(p.init)->values[0];
        for (size_t i = 0; i < cands.size(); ++i) {
            if (!eval(cands[i].update, env, 0)) {
                cands.erase(cands.begin() + static_cast<long>(i));
                changed = true;
                break;
            }
        }
    }

    // The exit test: follow unconditional branches from the header; the first
    // conditional branch with the merge block as a target is a top test.
    // Otherwise look for a latch that branches to the header or the merge.
    const Block *exit_block = nullptr;
    bool top_tested = false;
    {
        const Block *b = &header;
        std::set<std::string> seen;
        while (b && seen.insert(b->label).second) {
            loop->prefix.insert(b->label);
            const Inst &term = b->insts.back();
            if (term.op == "OpBranchConditional") {
                if (term.args.size() >= 3 && (term.args[1] == loop->merge || term.args[2] == loop->merge)) {
                    exit_block = b;
                    top_tested = true;
                }
                break;
            }
            if (term.op != "OpBranch" || term.args.empty() || term.args[0] == header.label) break;
            auto it = blocks_.find(term.args[0]);
            b = it == blocks_.end() ? nullptr : it->second;
        }
    }
    if (!exit_block) {
        loop->prefix.clear();
        for (const std::string &label : loop->body) {
            const Block *b = blocks_.at(label);
            const Inst &term = b->insts.back();
            if (term.op == "OpBranchConditional" && term.args.size() >= 3 &&
                ((term.args[1] == header.label && term.args[2] == loop->merge) ||
                 (term.args[2] == header.label && term.args[1] == loop->merge))) {
                exit_block = b;
                break;
            }
        }
    }
    if (!exit_block) {
        *err = "unbounded loop: the " + where +
               " has no exit test on a compile-time trip count (ps_2_x has no flow control; "
               "use a constant-bounded for loop)";
        return false;
    }
    const Inst &term = exit_block->insts.back();
    const std::string &cond = term.args[0];
    const bool exit_when_true = term.args[1] == loop->merge;

    // Simulate.  Each pass runs the prefix (or the whole body for a bottom
    // test), evaluates the exit test, then runs the rest and steps.
    long runs = 0, rest = 0;
    for (;;) {
        ++runs;
        std::optional<double> c = eval(cond, env, 0);
        if (!c) {
            *err = "unbounded loop: the exit condition of the " + where +
                   " is not a compile-time function of the loop counter";
            return false;
        }
        bool exits = (*c != 0.0) == exit_when_true;
        if (exits) break;
        if (top_tested) ++rest;
        if (runs > kMaxTrips) {
            *err = "unbounded loop: the " + where + " runs more than " + std::to_string(kMaxTrips) + " iterations";
            return false;
        }
        std::map<std::string, double> next = env;
        for (const Phi &p : cands) {
            std::optional<double> u = eval(p.update, env, 0);
            if (!u) {
                *err = "unbounded loop: the counter update of the " + where + " cannot be evaluated";
                return false;
            }
            next[p.id] = *u;
        }
        env = next;
    }
    if (top_tested) {
        loop->trips_prefix = runs;
        loop->trips_body = rest;
    } else {
        loop->trips_prefix = runs;
        loop->trips_body = runs;
    }
    for (const Phi &p : cands) {
        induction_.insert(p.id);
        induction_.insert(p.update);
    }
    return true;
}

// Values computed only from constants and induction variables fold away once
// a loop is unrolled (and spirv-opt already folded the rest).
void Counter::propagate_derived(const Function &f) {
    static const std::set<std::string> kOpaque = {
        "OpLoad", "OpAccessChain", "OpInBoundsAccessChain", "OpPhi", "OpFunctionCall", "OpVariable",
        "OpSampledImage", "OpImage", "OpFunctionParameter"};
    derived_.clear();
    for (const std::string &id : induction_) {
        const Inst *d = def(id);
        if (d && d->op == "OpPhi") derived_.insert(id);
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (const Block &b : f.blocks) {
            if (!reachable_.count(b.label)) continue;
            for (const Inst &in : b.insts) {
                if (in.result.empty() || derived_.count(in.result)) continue;
                if (kOpaque.count(in.op) || in.op.rfind("OpImage", 0) == 0) continue;
                if (in.op == "OpExtInst" && ext_set(in) != "GLSL.std.450") continue;
                std::vector<std::string> ids = id_operands(in);
                bool all = !ids.empty();
                for (const std::string &id : ids)
                    if (!is_const(id)) { all = false; break; }
                if (all) { derived_.insert(in.result); changed = true; }
            }
        }
    }
}

// mad fusion, dp2add fusion and _sat clamps.
void Counter::analyse_fusion(const Function &f) {
    auto same_block = [&](const std::string &a, const std::string &b) {
        auto ia = def_block_.find(a), ib = def_block_.find(b);
        return ia != def_block_.end() && ib != def_block_.end() && ia->second == ib->second;
    };
    for (const Block &b : f.blocks) {
        for (const Inst &in : b.insts) {
            if ((in.op != "OpFAdd" && in.op != "OpFSub") || in.args.size() != 2) continue;
            if (derived_.count(in.result)) continue;
            bool fused = false;
            for (const std::string &a : in.args) {
                const Inst *d = def(a);
                if (d && (d->op == "OpFMul" || d->op == "OpVectorTimesScalar") && uses(a) == 1 &&
                    same_block(a, in.result) && !fused_mul_.count(a) && !derived_.count(a)) {
                    fused_mul_.insert(a);
                    fused = true;
                    break;
                }
            }
            if (fused) continue;
            for (const std::string &a : in.args) {
                const Inst *d = def(a);
                if (d && d->op == "OpDot" && !d->args.empty() && comps(value_type(d->args[0])) == 2 &&
                    uses(a) == 1 && same_block(a, in.result) && !derived_.count(a)) {
                    free_add_.insert(in.result);
                    break;
                }
            }
        }
    }
    // _sat: needs the fusion sets above to know whether x is a real ALU instruction.
    for (const Block &b : f.blocks) {
        for (const Inst &in : b.insts) {
            std::string name = ext_name(in);
            if (name != "FClamp" && name != "NClamp") continue;
            if (!const_all(ext_arg(in, 1), 0.0) || !const_all(ext_arg(in, 2), 1.0)) continue;
            // x must be a single-use ALU result, or a vector built only from
            // single-use ALU results (each lane's instruction takes the _sat).
            auto alu_result = [&](const std::string &id) {
                const Inst *d = def(id);
                if (!d || uses(id) != 1 || !same_block(id, in.result)) return false;
                Cost c = cost(*d, *blocks_.at(def_block_.at(id)));
                return c.alu >= 1 && c.tex == 0;
            };
            const std::string x = ext_arg(in, 0);
            const Inst *d = def(x);
            bool sat = alu_result(x);
            if (!sat && d && d->op == "OpCompositeConstruct" && uses(x) == 1 && same_block(x, in.result)) {
                sat = true;
                for (const std::string &lane : d->args)
                    if (!alu_result(lane)) sat = false;
            }
            if (sat) sat_clamp_.insert(in.result);
        }
    }
}

int Counter::div_cost(const Inst &in) const {
    if (in.args.size() != 2) return 2;
    const std::string &num = in.args[0], &den = in.args[1];
    int rcp;
    if (is_const(den)) {
        rcp = 0;  // reciprocal folded into a constant
    } else {
        const Inst *d = def(den);
        rcp = comps(in.type);
        if (d && d->op == "OpCompositeConstruct" && !d->args.empty()) {
            bool splat = true;
            for (const std::string &a : d->args) if (a != d->args[0]) splat = false;
            if (splat) rcp = 1;
        }
    }
    int mul = (const_all(num, 1.0) && rcp > 0) ? 0 : 1;
    return rcp + mul;
}

Cost Counter::ext_cost(const Inst &in) const {
    Cost c;
    const std::string set = ext_set(in);
    if (set != "GLSL.std.450") {
        c.name = set.rfind("NonSemantic.", 0) == 0 ? std::string() : "other:" + set;
        c.alu = c.name.empty() ? 0 : 1;
        return c;
    }
    const std::string name = ext_name(in);
    c.name = name;
    const int n = comps(in.type);
    const std::string x = ext_arg(in, 0);
    if (name == "FClamp" || name == "NClamp") {
        if (const_all(ext_arg(in, 1), 0.0) && const_all(ext_arg(in, 2), 1.0)) c.alu = sat_clamp_.count(in.result) ? 0 : 1;
        else c.alu = 2;
        return c;
    }
    if (name == "Step") { c.alu = const_all(x, 0.0) ? 1 : 2; return c; }
    if (name == "SmoothStep") { c.alu = (is_const(x) && is_const(ext_arg(in, 1))) ? 4 : 7; return c; }
    if (name == "Length") { c.alu = comps(value_type(x)) > 1 ? 3 : 1; return c; }
    if (name == "Distance") {
        int w = comps(value_type(x));
        if (w <= 1) w = comps(value_type(ext_arg(in, 1)));
        c.alu = w > 1 ? 4 : 2;
        return c;
    }
    if (name == "Determinant" || name == "MatrixInverse") {
        const TypeInfo &t = type_of(value_type(x));
        int size = t.kind == TypeInfo::Matrix ? t.cols : 4;
        static const int det[] = {2, 2, 2, 3, 12}, inv[] = {4, 4, 4, 12, 36};
        size = size < 2 ? 2 : (size > 4 ? 4 : size);
        c.alu = name == "Determinant" ? det[size] : inv[size];
        return c;
    }
    auto r = ext_rules_.find(name);
    if (r == ext_rules_.end()) { c.name = "other:" + name; c.alu = 1; return c; }
    int slots = r->second->fixed + r->second->per_comp * n;
    if (r->second->unit == Unit::Tex) c.tex = slots;
    else if (r->second->unit == Unit::Alu) c.alu = slots;
    return c;
}

Cost Counter::cost(const Inst &in, const Block &b) const {
    Cost c;
    c.name = in.op;
    const std::string &op = in.op;
    if (!in.result.empty() && derived_.count(in.result)) return Cost();  // folds to a constant
    if (op == "OpExtInst") return ext_cost(in);
    if (op == "OpFMul" || op == "OpVectorTimesScalar") { c.alu = fused_mul_.count(in.result) ? 0 : 1; return c; }
    if (op == "OpFAdd" || op == "OpFSub") { c.alu = free_add_.count(in.result) ? 0 : 1; return c; }
    if (op == "OpDot") {
        c.alu = (!in.args.empty() && comps(value_type(in.args[0])) == 2) ? 2 : 1;
        return c;
    }
    if (op == "OpFDiv") { c.alu = div_cost(in); return c; }
    if (op == "OpFMod" || op == "OpFRem") { c.alu = div_cost(in) + 2; return c; }
    if (op == "OpPhi") {
        int incoming = static_cast<int>(in.args.size() / 2);
        c.alu = b.loop_header || incoming < 2 ? 0 : incoming - 1;
        return c;
    }
    if (op == "OpSwitch") {
        if (in.args.empty() || is_const(in.args[0])) return c;
        for (size_t i = 2; i < in.args.size(); i += 2)
            if (std::strtod(in.args[i].c_str(), nullptr) != 0.0) ++c.alu;
        return c;
    }
    if (op.rfind("OpFOrd", 0) == 0 || op.rfind("OpFUnord", 0) == 0) {
        bool vs_zero = false;
        for (const std::string &a : in.args) if (const_all(a, 0.0)) vs_zero = true;
        c.alu = vs_zero ? 0 : 1;
        return c;
    }
    if (op == "OpVectorShuffle" || op == "OpCompositeConstruct" || op == "OpCompositeInsert") {
        // Which operands feed lanes of the result?
        std::vector<std::string> srcs;
        if (op == "OpVectorShuffle" && in.args.size() >= 2) {
            int w0 = comps(value_type(in.args[0]));
            for (size_t i = 2; i < in.args.size(); ++i) {
                int lane = std::atoi(in.args[i].c_str());
                if (in.args[i] == "0xffffffff") continue;  // undefined lane
                srcs.push_back(lane < w0 ? in.args[0] : in.args[1]);
            }
        } else if (op == "OpCompositeInsert" && in.args.size() >= 2) {
            srcs = {in.args[0], in.args[1]};
        } else {
            srcs = in.args;
        }
        bool any_const = false, any_var = false;
        for (const std::string &s : srcs) {
            if (!is_id(s)) continue;
            if (is_const(s)) any_const = true; else any_var = true;
        }
        c.alu = (any_const && any_var) ? 1 : 0;
        if (c.alu) c.name = op + " (constant lanes)";
        return c;
    }
    if (op == "OpMatrixTimesVector" || op == "OpVectorTimesMatrix") { c.alu = comps(in.type); return c; }
    if (op == "OpMatrixTimesMatrix") {
        const TypeInfo &t = type_of(in.type);
        c.alu = t.cols * t.comps;
        return c;
    }
    if (op == "OpMatrixTimesScalar" || op == "OpOuterProduct") { c.alu = type_of(in.type).cols; return c; }

    auto r = core_rules_.find(op);
    if (r == core_rules_.end()) {
        c.name = "other:" + op;
        c.alu = 1;
        return c;
    }
    int slots = r->second->fixed + r->second->per_comp * comps(in.type);
    if (r->second->unit == Unit::Tex) c.tex = slots;
    else if (r->second->unit == Unit::Alu) c.alu = slots;
    return c;
}

bool Counter::analyse_function(const Function &f, std::string *err) {
    defs_.clear(); def_block_.clear(); use_count_.clear(); blocks_.clear(); reachable_.clear();
    loops_.clear(); induction_.clear(); derived_.clear(); fused_mul_.clear(); free_add_.clear(); sat_clamp_.clear();
    if (f.blocks.empty()) { *err = "fragment entry point has no body"; return false; }

    for (const Block &b : f.blocks) {
        blocks_[b.label] = &b;
        if (b.insts.empty()) { *err = "empty block " + b.label; return false; }
        for (const Inst &in : b.insts) {
            if (!in.result.empty()) { defs_[in.result] = &in; def_block_[in.result] = b.label; }
            for (const std::string &id : id_operands(in)) ++use_count_[id];
        }
    }
    std::vector<std::string> work{f.blocks.front().label};
    reachable_.insert(work.back());
    while (!work.empty()) {
        std::string l = work.back();
        work.pop_back();
        auto it = blocks_.find(l);
        if (it == blocks_.end()) { *err = "branch to unknown block " + l; return false; }
        for (const std::string &s : it->second->succ)
            if (reachable_.insert(s).second) work.push_back(s);
    }
    for (const Block &b : f.blocks) {
        if (!reachable_.count(b.label) || !b.loop_header) continue;
        LoopInfo loop;
        if (!analyse_loop(b, &loop, err)) return false;
        loops_.push_back(loop);
    }
    propagate_derived(f);
    analyse_fusion(f);
    return true;
}

bool Counter::count(BudgetCounts *out, std::string *err) {
    const Function *entry = nullptr;
    for (const Function &f : m_.functions) if (f.id == m_.fragment_entry) entry = &f;
    if (!entry) { *err = "fragment entry point " + m_.fragment_entry + " not found"; return false; }
    if (!analyse_function(*entry, err)) return false;

    BudgetCounts r;
    std::map<std::string, std::set<std::string>> outputs;  // output variable -> blocks storing it
    for (const Block &b : entry->blocks) {
        if (!reachable_.count(b.label)) continue;
        long mult = 1;
        for (const LoopInfo &l : loops_) {
            if (!l.body.count(b.label)) continue;
            mult *= l.prefix.count(b.label) ? l.trips_prefix : l.trips_body;
            if (mult > kMaxMultiplier) { *err = "nested loops run more than 2^20 iterations"; return false; }
        }
        for (const Inst &in : b.insts) {
            if (in.op == "OpFunctionCall") {
                *err = "a function call survived spirv-opt -O (" + in.args.front() + "); cannot count it";
                return false;
            }
            if (in.op == "OpStore" && !in.args.empty()) {
                std::string var = output_variable(in.args[0]);
                if (!var.empty()) outputs[var].insert(b.label);
                continue;
            }
            Cost c = cost(in, b);
            if (c.alu == 0 && c.tex == 0) continue;
            int alu = static_cast<int>(c.alu * mult), tex = static_cast<int>(c.tex * mult);
            r.alu += alu;
            r.tex += tex;
            r.by_op[c.name] += alu + tex;
        }
    }
    for (const auto &o : outputs) {
        r.alu += 1;
        r.by_op["output mov (oC#/oDepth)"] += 1;
        if (o.second.size() > 1) {  // written on several flattened paths: cmp selects the value
            int extra = static_cast<int>(o.second.size()) - 1;
            r.alu += extra;
            r.by_op["output merge cmp"] += extra;
        }
    }
    *out = r;
    return true;
}

}  // namespace

// ----------------------------------------------------------------------------
// 6. Public API
// ----------------------------------------------------------------------------
bool budget_count_fragment(const std::string &glsl330_source, BudgetCounts *out, std::string *err) {
    std::string dummy;
    std::string &e = err ? *err : dummy;
    e.clear();
    if (!out) { e = "budget_count_fragment: out is null"; return false; }
    *out = BudgetCounts();

    std::string source;
    if (!prepare_source(glsl330_source, &source, &e)) return false;

    TempDir dir;
    if (!dir.ok()) { e = dir.error(); return false; }
    const std::string frag = dir.file("fragment.frag"), spv = dir.file("fragment.spv"),
                      opt = dir.file("fragment.opt.spv"), dis = dir.file("fragment.spvasm"),
                      log_out = dir.file("tool.out"), log_err = dir.file("tool.err");
    if (!write_file(frag, source, &e)) return false;

    struct Step { const char *what; std::vector<std::string> argv; };
    const Step steps[] = {
        {"glslangValidator", {"glslangValidator", "-V", "-R", "-S", "frag", "--amb", "--aml", "-o", spv, frag}},
        {"spirv-opt", {"spirv-opt", "-O", spv, "-o", opt}},
        {"spirv-dis", {"spirv-dis", "--no-color", "--no-header", opt, "-o", dis}},
    };
    for (const Step &s : steps) {
        int code = 0;
        if (!run_tool(s.argv, log_out, log_err, &code, &e)) return false;
        if (code != 0) {
            // glslang prints its compile log on stdout, the spirv tools on stderr.
            std::string log = read_file(log_out) + "\n" + read_file(log_err);
            e = std::string(s.what) + " failed (exit " + std::to_string(code) + "):\n" +
                clean_log(log, dir.path(), "fragment.frag");
            return false;
        }
    }

    Module m;
    if (!parse_disassembly(read_file(dis), &m, &e)) return false;
    Counter counter(m);
    BudgetCounts r;
    if (!counter.count(&r, &e)) return false;
    *out = r;
    return true;
}

std::string budget_weight_table_markdown() {
    std::ostringstream md;
    md << "| SPIR-V instruction | DX9 equivalent | slots |\n";
    md << "|---|---|---|\n";
    for (const Rule &r : kRules) {
        std::istringstream ss(r.ops);
        std::string name, names;
        while (ss >> name) names += (names.empty() ? "" : ", ") + name;
        if (r.ext) names += " (GLSL.std.450)";
        md << "| " << names << " | " << r.dx9 << " | " << rule_slots_text(r) << " |\n";
    }
    md << "| any other instruction | unknown | 1, reported as `other:<name>` |\n";
    return md.str();
}

// ----------------------------------------------------------------------------
// 7. Mesa NIR cross-check
// ----------------------------------------------------------------------------
// Mesa 22.x prints SSA definitions as
//     vec1 32 ssa_9 = fmul ssa_8.x, ssa_0
//     vec4 32 ssa_8 = (float32)tex ssa_7 (coord), 1 (texture), 1 (sampler)
// and newer Mesa as "con 32x4 %8 = ..." or "32 %9 = ...".  We accept both.
namespace {

struct NirSection {
    std::string sha1;
    std::vector<std::string> lines;
};

// Width of a NIR destination from the tokens before "=" (vecN, or BITSxN).
int nir_dest_width(const std::vector<std::string> &lhs) {
    for (const std::string &t : lhs) {
        if (t.rfind("vec", 0) == 0 && t.size() > 3) return std::atoi(t.c_str() + 3);
        size_t x = t.find('x');
        if (x != std::string::npos && x > 0 && std::isdigit(static_cast<unsigned char>(t[0])))
            return std::atoi(t.c_str() + x + 1);
    }
    return 1;
}

}  // namespace

bool budget_count_nir_text(const std::string &nir_dump, int *scalar_alu, int *tex, std::string *err) {
    std::string dummy;
    std::string &e = err ? *err : dummy;
    e.clear();
    if (!scalar_alu || !tex) { e = "budget_count_nir_text: null output"; return false; }
    *scalar_alu = 0;
    *tex = 0;

    // Split the dump into shader sections and keep the fragment ones.
    std::vector<NirSection> frags;
    NirSection *cur = nullptr;
    std::istringstream in(nir_dump);
    std::string line;
    while (std::getline(in, line)) {
        std::string t = trim(line);
        if (t.rfind("shader: MESA_SHADER_", 0) == 0) {
            if (t == "shader: MESA_SHADER_FRAGMENT") { frags.push_back(NirSection()); cur = &frags.back(); }
            else cur = nullptr;
            continue;
        }
        if (t.rfind("NIR before handing off", 0) == 0) { cur = nullptr; continue; }
        if (!cur) continue;
        if (t.rfind("source_sha1:", 0) == 0) cur->sha1 = t;
        cur->lines.push_back(t);
    }
    if (frags.empty()) { e = "no \"shader: MESA_SHADER_FRAGMENT\" section in the NIR dump (was ST_DEBUG=nir set?)"; return false; }
    for (const NirSection &s : frags) {
        if (s.sha1 != frags.front().sha1) {
            e = "the NIR dump holds " + std::to_string(frags.size()) +
                " different fragment shaders; pass the dump of one shader";
            return false;
        }
    }

    static const std::set<std::string> kFree = {"mov", "vec2", "vec3", "vec4", "vec5", "vec8", "vec16",
                                                "load_const", "deref_var", "deref_array", "deref_struct",
                                                "deref_cast", "intrinsic", "phi", "undefined", "ssa_undef"};
    static const std::set<std::string> kTex = {"tex", "txb", "txl", "txd", "txf", "txf_ms", "tg4"};
    int alu = 0, tx = 0;
    bool saw_impl = false;
    for (const std::string &t : frags.front().lines) {
        if (t.rfind("impl ", 0) == 0) saw_impl = true;
        size_t eq = t.find(" = ");
        if (eq == std::string::npos) continue;
        std::vector<std::string> lhs = tokenize(t.substr(0, eq));
        if (lhs.empty()) continue;
        const std::string &dst = lhs.back();
        bool is_dest = dst.rfind("ssa_", 0) == 0 || (dst.size() > 1 && dst[0] == '%' &&
                                                     std::isdigit(static_cast<unsigned char>(dst[1])));
        if (!is_dest || lhs.size() < 2) continue;  // e.g. "intrinsic store_deref (...) (wrmask=...)"
        std::vector<std::string> rhs = tokenize(t.substr(eq + 3));
        if (rhs.empty()) continue;
        std::string op = rhs[0];
        if (!op.empty() && op[0] == '(') {  // "(float32)tex"
            size_t close = op.find(')');
            op = close == std::string::npos ? op : op.substr(close + 1);
        }
        size_t dot = op.find('.');  // saturate/exact suffixes in some Mesa versions
        if (dot != std::string::npos) op = op.substr(0, dot);
        if (op.empty()) continue;
        if (kTex.count(op)) { ++tx; continue; }
        if (op.rfind("tx", 0) == 0 || op == "lod" || op == "query_levels" || op == "texture_samples" ||
            op == "samples_identical" || op == "fragment_fetch" || op == "fragment_mask_fetch")
            continue;  // texture queries: not counted
        if (kFree.count(op) || op[0] == '@') continue;  // '@name': intrinsic in newer Mesa
        alu += nir_dest_width(lhs);
    }
    if (!saw_impl) { e = "the fragment section of the NIR dump has no \"impl\" body"; return false; }
    *scalar_alu = alu;
    *tex = tx;
    return true;
}
