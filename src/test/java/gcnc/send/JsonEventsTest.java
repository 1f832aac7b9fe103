package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The JSON event stream: one object a line, the record's components as fields, NaN as null. */
class JsonEventsTest {
    @Test
    void anEventIsOneObjectWithItsFieldsInOrder() {
        assertEquals("{\"event\":\"stopped\",\"reason\":\"E821\",\"completed\":7,\"executing\":8,"
                + "\"where\":\"X40.000 Z-1.500 (Galil counts 131927,19685)\",\"wherePolled\":false,\"resumeAt\":\"8\","
                + "\"resume\":\"gcnc run \\\"a b\\\".nc --resume-at 8\"}",
                JsonEvents.json(new Event.Stopped("E821", 7, 8, "X40.000 Z-1.500 (Galil counts 131927,19685)", false, "8",
                        "gcnc run \"a b\".nc --resume-at 8")));
    }

    @Test
    void unknownNumbersAreNullAndArraysAreArrays() {
        String s = JsonEvents.json(new Event.Status(12, 8, "80", null, new double[] {40, -1.5}, new double[] {131927, 19685},
                Double.NaN, true, false, 1200, "cw", 0.25, 8.5, 1, false));
        assertEquals("{\"event\":\"status\",\"dmcLine\":12,\"line\":8,\"number\":\"80\",\"file\":null,\"program\":[40,-1.5],"
                + "\"counts\":[131927,19685],\"feed\":null,\"perRev\":true,\"inch\":false,\"rpm\":1200,\"spindle\":\"cw\","
                + "\"progress\":0.25,\"secondsLeft\":8.5,\"override\":1,\"held\":false}", s);
        assertEquals("step-wait", JsonEvents.kebab("StepWait"));
    }

    /** A program stop's comment is the program's text: quotes, backslashes and control characters escaped (RFC 8259 §7). */
    @Test
    void textIsEscaped() {
        assertEquals("{\"event\":\"program-stop\",\"line\":4,\"number\":\"40\",\"comment\":\"C:\\\\PARTS\\n\\t\\\"A\\\"\\u0001\"}",
                JsonEvents.json(new Event.ProgramStop(4, "40", "C:\\PARTS\n\t\"A\"\u0001")));
    }
}
