package gcnc.cli;

import gcnc.dmc.Form;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** {@code --form program|stream} of compile and run: the form by its name, or a usage error (exit 2). */
final class FormConverter implements ITypeConverter<Form> {
    @Override
    public Form convert(String value) {
        Form f = Form.of(value);
        if (f == null) {
            throw new TypeConversionException("--form " + value + ": say program or stream");
        }
        return f;
    }
}
