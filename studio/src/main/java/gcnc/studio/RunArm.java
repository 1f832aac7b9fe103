package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.send.ResumePoint;

/**
 * A program armed on a controller: what start needs (the program as compiled, its file's version then,
 * the target and how to run it) and the arm's answer.
 *
 * @param id      what start must name (random: a page starts only what it armed)
 * @param address the virtual controller's {@code 127.0.0.1:PORT}, null for another target
 */
record RunArm(String id, String name, String version, RunTarget target, String address, boolean step,
              ResumePoint resumeAt, RunProgram program, Runs.Context context, JsonObject answer) {
}
